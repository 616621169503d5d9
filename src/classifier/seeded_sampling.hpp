#pragma once
// Reproducible random choices for training: a seeded subset (recipes asking for fewer samples than a set
// holds) and a stratified held-out split (validation). std::mt19937_64 with a Fisher-Yates shuffle written
// here, so the same seed picks the same samples with every compiler and standard library.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rdsf {

/// `k` distinct indices of [0, n), ascending; all of them when k >= n.
std::vector<std::size_t> seeded_subset(std::size_t n, std::size_t k, std::uint64_t seed);

struct HoldOutSplit {
  std::vector<std::size_t> train;       ///< ascending
  std::vector<std::size_t> validation;  ///< ascending
};

/// Holds out round(fraction * count) samples of each label (1/0) for validation. fraction 0 keeps all for
/// training; a class with at least 2 samples keeps at least one on each side.
HoldOutSplit stratified_split(const std::vector<int>& labels, double fraction, std::uint64_t seed);

}  // namespace rdsf
