#pragma once
// Weighted per-bin histograms of binned features: the inner loop of a Real AdaBoost round (issue 17).
// For a feature f, sums[2 * bin + y] is the total weight of the samples of class y (1 person, 0 not) whose
// bin of f is `bin`. A histogram is a scatter-add: one table update (a load and a store of a double) per
// byte of bins, so a round costs at least one table update per sample and feature, not the streaming of
// the bins (docs/performance.md states the machine's limit).
//
// Floating-point sums depend on their order, and the models must be the same bits whatever the code path
// and thread count. Each function below fixes its order exactly (the "chains"): the weights of one chain
// are added in increasing sample order, and the chains are combined as stated. The functions only choose
// how many features share one pass over the weights and how the bins are loaded, never the order.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rdsf {

constexpr int kMaxHistogramBins = 256;

/// Two-part sums of `count` features (1..8) when the samples are ordered positives first ([0, positives)
/// have y = 1, [positives, n) y = 0): per bin and class, the weights at even and at odd positions within
/// the class are summed separately in sample order, then added (even + odd). The weight of a sample is
/// loaded once for all the features, and eight bins of a feature are loaded at once.
/// sums[k] receives 2 * bin_count values.
void two_part_histograms(const std::uint8_t* const* bins, int count, const double* w, std::size_t positives,
                         std::size_t n, int bin_count, double* const* sums);

/// The samples of the nodes of one tree level (or the one node of a depth-1 round over a subset), for the
/// four-part sums of node_histograms: node k's members are the samples listed for it, in increasing order;
/// member r of a node with m members goes to part r % 4 when r < m / 4 * 4 and to part 0 otherwise
/// (the tail). Samples of no node are skipped.
class NodeSamples {
 public:
  /// `members[k]` ascending, disjoint; `y` the class (0 / 1) of every sample.
  NodeSamples(const std::vector<const std::vector<std::size_t>*>& members, const std::vector<std::uint8_t>& y,
              std::size_t n);
  std::size_t nodes() const { return nodes_; }
  /// Samples in some node, ascending; all n of them when dense().
  const std::vector<std::uint32_t>& samples() const { return samples_; }
  bool dense() const { return dense_; }
  /// Per entry of samples(): ((node * 4 + part) * 2 + y), the index of its table.
  const std::vector<std::uint32_t>& table() const { return table_; }
  /// Weights of samples(), in that order (refreshed by gather_weights).
  const std::vector<double>& weights() const { return weights_; }
  void gather_weights(const std::vector<double>& w);

 private:
  std::size_t nodes_ = 0;
  bool dense_ = false;
  std::vector<std::uint32_t> samples_, table_;
  std::vector<double> weights_;
};

/// Four-part sums of `count` features (1..4) for every node of `nodes`: per node, bin and class, the four
/// parts (NodeSamples) each summed in sample order, then added as (0 + 1) + (2 + 3) -- the sums of the
/// straightforward one-feature, one-node loop. sums[k * nodes.nodes() + node] receives 2 * bin_count
/// values for feature k.
void node_histograms(const std::uint8_t* const* bins, int count, const NodeSamples& nodes, int bin_count,
                     double* const* sums);

}  // namespace rdsf
