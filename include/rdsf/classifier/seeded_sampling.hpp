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

/// A seeded random order of [0, n) (Fisher-Yates, the same on every standard library).
std::vector<std::size_t> seeded_permutation(std::size_t n, std::uint64_t seed);

struct HoldOutSplit {
  std::vector<std::size_t> train;       ///< ascending
  std::vector<std::size_t> validation;  ///< ascending
};

/// Holds out round(fraction * count) samples of each label (1/0) for validation. fraction 0 keeps all for
/// training; a class with at least 2 samples keeps at least one on each side.
HoldOutSplit stratified_split(const std::vector<int>& labels, double fraction, std::uint64_t seed);

/// Holds out whole groups (group[i] is sample i's group id, any numbers): no group has samples on both
/// sides. Groups are taken in a seeded random order; a group joins the validation side while that brings a
/// class still short of round(fraction * count) closer to it and takes no class beyond 1.5 times its share,
/// so each class ends near `fraction`; when that holds out none of a class (a few large groups), the first
/// group with some of it is held out too. Samples with counts[i] == false (augmented copies) go with their
/// group but are not counted. Throws Error when a class ends up empty on either side (too few groups).
HoldOutSplit group_split(const std::vector<int>& labels, const std::vector<std::size_t>& group, double fraction,
                         std::uint64_t seed, const std::vector<bool>& counts = {});

}  // namespace rdsf
