#pragma once
// One weak classifier of a boosted model.
//   - kind Lut (native Real AdaBoost, domain partitioning): responses[bin_of(x[feature])], one real response
//     per bin of the model's BinScheme;
//   - kind Stump (the OpenCV backend's depth-1 trees): x[feature] <= threshold ? left : right, exactly as
//     cv::ml::DTrees evaluates an ordered split (OpenCV's "inversed" splits are stored swapped);
//   - kind Tree (native, depth d >= 2): a complete binary tree of look-up tables, nodes[0] the root and
//     nodes[2k+1], nodes[2k+2] the children of node k (2^d - 1 nodes). An inner node routes a sample to its
//     right child when its table's entry at the sample's bin is > 0 and to its left child otherwise (the
//     trainer writes -1 / +1: a split of the bins at a threshold); the leaf's table gives the response.
//     `feature` is the root's feature.
#include <cstddef>
#include <vector>

#include "rdsf/classifier/bin_scheme.hpp"

namespace rdsf {

/// One look-up table of a tree: the feature it reads and one response per bin.
struct LutNode {
  int feature = 0;
  std::vector<double> responses;
  bool operator==(const LutNode& o) const { return feature == o.feature && responses == o.responses; }
};

struct WeakClassifier {
  enum class Kind { Lut, Stump, Tree };
  Kind kind = Kind::Lut;
  int feature = 0;                 ///< index into the feature vector (the root's for a tree)
  std::vector<double> responses;   ///< Lut: one per bin
  double threshold = 0.0;          ///< Stump
  double left = 0.0, right = 0.0;  ///< Stump: responses at or below / above the threshold
  std::vector<LutNode> nodes;      ///< Tree: 2^depth - 1 nodes, breadth first

  /// Response of a Lut or Stump to the value of its feature (not for trees: use respond_row).
  double respond(float value, const BinScheme& bins) const {
    if (kind == Kind::Lut) return responses[static_cast<std::size_t>(bins.bin_of(value))];
    return value <= threshold ? left : right;
  }
  /// Response to a whole feature row (every kind).
  double respond_row(const float* row, const BinScheme& bins) const {
    if (kind != Kind::Tree) return respond(row[feature], bins);
    std::size_t k = 0;
    for (;;) {
      const LutNode& node = nodes[k];
      const double r = node.responses[static_cast<std::size_t>(bins.bin_of(row[node.feature]))];
      const std::size_t child = 2 * k + (r > 0.0 ? 2 : 1);
      if (child >= nodes.size()) return r;
      k = child;
    }
  }
  /// Tree depth: 1 for Lut and Stump.
  int depth() const {
    int d = 1;
    while ((std::size_t{1} << d) - 1 < nodes.size()) ++d;
    return kind == Kind::Tree ? d : 1;
  }
  /// Every feature index it reads (the root's first).
  std::vector<int> features_read() const {
    if (kind != Kind::Tree) return {feature};
    std::vector<int> out;
    for (const LutNode& n : nodes) out.push_back(n.feature);
    return out;
  }
  bool operator==(const WeakClassifier& o) const {
    return kind == o.kind && feature == o.feature && responses == o.responses && threshold == o.threshold &&
           left == o.left && right == o.right && nodes == o.nodes;
  }
};

}  // namespace rdsf
