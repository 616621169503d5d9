#include "rdsf/classifier/binned_forest.hpp"

#include <algorithm>

#include "rdsf/classifier/bin_row.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {

bool BinnedForest::supports(const BoostedModel& model) {
  for (const WeakClassifier& w : model.weak_classifiers()) {
    if (w.kind == WeakClassifier::Kind::Stump) return false;
  }
  return true;
}

BinnedForest::BinnedForest(const BoostedModel& model, int row_size) : bins_(model.bins()), row_size_(row_size) {
  if (!supports(model)) throw Error("binned forest: the model has stumps, which read values, not bins");
  auto add_node = [&](int feature, const std::vector<double>& responses, bool leaf) {
    if (feature < 0 || feature >= row_size_) {
      throw Error("binned forest: feature " + std::to_string(feature) + " outside a row of " + std::to_string(row_size_));
    }
    Node node{feature, 0};
    if (leaf) {
      node.table = static_cast<std::uint32_t>(response_.size());
      response_.insert(response_.end(), responses.begin(), responses.end());
    } else {
      node.table = static_cast<std::uint32_t>(right_.size());
      for (const double r : responses) right_.push_back(r > 0.0 ? 1 : 0);
    }
    nodes_.push_back(node);
  };
  for (const WeakClassifier& w : model.weak_classifiers()) {
    Weak flat{static_cast<std::uint32_t>(nodes_.size()), 0};
    if (w.kind == WeakClassifier::Kind::Lut) {
      add_node(w.feature, w.responses, true);
    } else {  // a complete tree: nodes [0, 2^(d-1) - 1) are inner, the rest leaves
      flat.inner_levels = static_cast<std::uint32_t>(w.depth() - 1);
      const std::size_t inner = (std::size_t{1} << flat.inner_levels) - 1;
      for (std::size_t k = 0; k < w.nodes.size(); ++k) add_node(w.nodes[k].feature, w.nodes[k].responses, k >= inner);
    }
    weak_.push_back(flat);
  }
}

double BinnedForest::score_bins(const std::uint8_t* bins, std::size_t rounds) const {
  const Node* nodes = nodes_.data();
  const std::uint8_t* right = right_.data();
  const double* response = response_.data();
  double sum = 0.0;
  const std::size_t n = std::min(rounds, weak_.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Weak& w = weak_[i];
    const Node* tree = nodes + w.first_node;
    std::uint32_t k = 0;
    for (std::uint32_t level = 0; level < w.inner_levels; ++level) {
      k = 2 * k + 1 + right[tree[k].table + bins[tree[k].feature]];
    }
    sum += response[tree[k].table + bins[tree[k].feature]];
  }
  return sum;
}

double BinnedForest::score(const float* row, std::size_t rounds) const {
  constexpr int kOnStack = 1024;
  std::uint8_t on_stack[kOnStack];
  std::vector<std::uint8_t> on_heap;
  std::uint8_t* bins = on_stack;
  if (row_size_ > kOnStack) {
    on_heap.resize(static_cast<std::size_t>(row_size_));
    bins = on_heap.data();
  }
  bin_row(bins_, row, row_size_, bins);
  return score_bins(bins, rounds);
}

}  // namespace rdsf
