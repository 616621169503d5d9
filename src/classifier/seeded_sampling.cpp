#include "rdsf/classifier/seeded_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "rdsf/classifier/dense_groups.hpp"
#include "rdsf/core/error.hpp"

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

std::vector<std::size_t> seeded_permutation(std::size_t n, std::uint64_t seed) {
  std::vector<std::size_t> items(n);
  std::iota(items.begin(), items.end(), std::size_t{0});
  std::mt19937_64 rng(seed);
  shuffle_prefix(items, n, rng);
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

HoldOutSplit group_split(const std::vector<int>& labels, const std::vector<std::size_t>& group, double fraction,
                         std::uint64_t seed, const std::vector<bool>& counts) {
  if (!(fraction > 0.0 && fraction < 1.0)) {
    throw Error("validation fraction " + std::to_string(fraction) + " is outside (0, 1) for a group split");
  }
  if (group.size() != labels.size() || (!counts.empty() && counts.size() != labels.size())) {
    throw Error("group split: labels, groups and counts differ in number");
  }
  // Dense group numbers (ascending ids), with their counted positives and negatives.
  const DenseGroups groups = dense_groups(group);
  const std::vector<std::size_t>& dense = groups.of_row;
  std::vector<std::size_t> pos(groups.count, 0), neg(groups.count, 0);
  std::size_t total_pos = 0, total_neg = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (!counts.empty() && !counts[i]) continue;
    (labels[i] == 1 ? pos : neg)[dense[i]] += 1;
    (labels[i] == 1 ? total_pos : total_neg) += 1;
  }
  const double want_pos = std::round(fraction * static_cast<double>(total_pos));
  const double want_neg = std::round(fraction * static_cast<double>(total_neg));
  const std::vector<std::size_t> order = seeded_permutation(groups.count, seed);
  std::vector<bool> held(groups.count, false);
  double got_pos = 0, got_neg = 0;
  for (std::size_t g : order) {
    if (got_pos >= want_pos && got_neg >= want_neg) break;
    const double p = static_cast<double>(pos[g]), n = static_cast<double>(neg[g]);
    const bool helps = (p > 0 && got_pos < want_pos) || (n > 0 && got_neg < want_neg);
    const bool fits = (p == 0 || got_pos + p <= 1.5 * want_pos + 1) && (n == 0 || got_neg + n <= 1.5 * want_neg + 1);
    if (!helps || !fits) continue;
    held[g] = true;
    got_pos += p;
    got_neg += n;
  }
  // Few large groups: when a class has none held out, the first group (same order) that has some, as long
  // as it leaves that class some training samples.
  for (int label : {1, 0}) {
    const double got = label == 1 ? got_pos : got_neg;
    const std::size_t total = label == 1 ? total_pos : total_neg;
    if (got > 0) continue;
    for (std::size_t g : order) {
      const std::size_t c = label == 1 ? pos[g] : neg[g];
      if (held[g] || c == 0 || c >= total) continue;
      held[g] = true;
      got_pos += static_cast<double>(pos[g]);
      got_neg += static_cast<double>(neg[g]);
      break;
    }
  }
  HoldOutSplit split;
  std::size_t val_pos = 0, val_neg = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const bool validation = held[dense[i]];
    (validation ? split.validation : split.train).push_back(i);
    if (validation && (counts.empty() || counts[i])) (labels[i] == 1 ? val_pos : val_neg) += 1;
  }
  const std::size_t train_pos = total_pos - val_pos, train_neg = total_neg - val_neg;
  if (val_pos == 0 || val_neg == 0 || train_pos == 0 || train_neg == 0) {
    throw Error("the group split leaves a class empty (" + std::to_string(groups.count) + " groups; validation " +
                std::to_string(val_pos) + " positives / " + std::to_string(val_neg) + " negatives, training " +
                std::to_string(train_pos) + " / " + std::to_string(train_neg) +
                "): give more recordings or clips, a larger validation fraction, or separate validation sets");
  }
  return split;
}

}  // namespace rdsf
