#pragma once
// A boosted model's look-up-table weak classifiers (kinds Lut and Tree) as flat tables that read a row of
// bins instead of a row of values: the row is binned once (bin_row, four values at a time, no division per
// node), then every weak classifier is walked without a data-dependent branch.
//   node k of a weak classifier: feature f_k and a table of count entries at table_k (BoostedModel checks
//     every table has bins().count responses);
//   inner node: k <- 2k + 1 + right[table_k + bin[f_k]], right[.] = (responses[.] > 0.0), exactly the
//     child WeakClassifier::respond_row takes; a Lut is a tree of one leaf;
//   leaf: H += response[table_k + bin[f_k]], the same double, added in the model's order from 0.0.
// So score() is bit for bit BoostedModel::score of the same row wherever bin_of is defined (bin_row.hpp).
// Stumps compare the value itself with a threshold: a model with one cannot be binned (supports()).
#include <cstdint>
#include <vector>

#include "rdsf/classifier/boosted_model.hpp"

namespace rdsf {

class BinnedForest {
 public:
  BinnedForest() = default;
  /// Throws Error when !supports(model) or a weak classifier reads a feature outside [0, row_size).
  BinnedForest(const BoostedModel& model, int row_size);

  /// True when every weak classifier is a Lut or a Tree.
  static bool supports(const BoostedModel& model);
  int row_size() const { return row_size_; }

  /// H(x) of a row of row_size() values; thread-safe. With `rounds`: the first `rounds` weak classifiers'
  /// sum alone (BoostedModel::score(features, rounds)).
  double score(const float* row, std::size_t rounds = SIZE_MAX) const;
  /// H(x) of a row already binned (row_size() bins from bin_row with the model's scheme).
  double score_bins(const std::uint8_t* bins, std::size_t rounds = SIZE_MAX) const;

 private:
  struct Node {
    std::int32_t feature;
    std::uint32_t table;  ///< into right_ (inner) or response_ (leaf)
  };
  struct Weak {
    std::uint32_t first_node;
    std::uint32_t inner_levels;  ///< depth - 1
  };
  BinScheme bins_;
  int row_size_ = 0;
  std::vector<Weak> weak_;
  std::vector<Node> nodes_;
  std::vector<std::uint8_t> right_;
  std::vector<double> response_;
};

}  // namespace rdsf
