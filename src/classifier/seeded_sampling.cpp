#include "classifier/seeded_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "core/error.hpp"

namespace rdsf {
namespace {

// Partial Fisher-Yates: the first k entries of `items` become a uniform random k-subset.
void shuffle_prefix(std::vector<std::size_t>& items, std::size_t k, std::mt19937_64& rng) {
  for (std::size_t i = 0; i < k && i + 1 < items.size(); ++i) {
    const std::size_t j = i + static_cast<std::size_t>(rng() % (items.size() - i));
    std::swap(items[i], items[j]);
  }
}

}  // namespace

std::vector<std::size_t> seeded_subset(std::size_t n, std::size_t k, std::uint64_t seed) {
  std::vector<std::size_t> items(n);
  std::iota(items.begin(), items.end(), std::size_t{0});
  if (k >= n) return items;
  std::mt19937_64 rng(seed);
  shuffle_prefix(items, k, rng);
  items.resize(k);
  std::sort(items.begin(), items.end());
  return items;
}

HoldOutSplit stratified_split(const std::vector<int>& labels, double fraction, std::uint64_t seed) {
  if (!(fraction >= 0.0 && fraction < 1.0)) {
    throw Error("validation fraction " + std::to_string(fraction) + " is outside [0, 1)");
  }
  HoldOutSplit split;
  std::mt19937_64 rng(seed);
  for (int label : {1, 0}) {
    std::vector<std::size_t> members;
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if (labels[i] == label) members.push_back(i);
    }
    std::size_t held = static_cast<std::size_t>(std::llround(fraction * static_cast<double>(members.size())));
    if (fraction > 0.0 && members.size() >= 2) held = std::clamp<std::size_t>(held, 1, members.size() - 1);
    shuffle_prefix(members, held, rng);
    split.validation.insert(split.validation.end(), members.begin(), members.begin() + static_cast<long>(held));
    split.train.insert(split.train.end(), members.begin() + static_cast<long>(held), members.end());
  }
  std::sort(split.train.begin(), split.train.end());
  std::sort(split.validation.begin(), split.validation.end());
  return split;
}

}  // namespace rdsf
