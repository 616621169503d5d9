#include "rdsf/classifier/real_adaboost.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "rdsf/classifier/bin_histograms.hpp"
#include "rdsf/classifier/parallel_chunks.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {
namespace {

constexpr int kMaxBins = kMaxHistogramBins;

// Per-bin weight sums of one feature: sums[2 * bin + y] (y = 1 person, 0 not). Four partial tables break
// the dependency between consecutive samples that fall into the same bin. The chosen feature's responses
// come from these sums; node_histograms (bin_histograms.hpp) takes the same sums for many features.
void feature_histogram(const std::uint8_t* bins, const std::uint8_t* y, const double* w, std::size_t n,
                       const std::size_t* subset, std::size_t subset_size, int bin_count, double* sums) {
  double part[4][2 * kMaxBins];
  const std::size_t width = static_cast<std::size_t>(2 * bin_count);
  for (auto& p : part) std::fill(p, p + width, 0.0);
  if (subset == nullptr) {
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) {
      part[0][(bins[i] << 1) | y[i]] += w[i];
      part[1][(bins[i + 1] << 1) | y[i + 1]] += w[i + 1];
      part[2][(bins[i + 2] << 1) | y[i + 2]] += w[i + 2];
      part[3][(bins[i + 3] << 1) | y[i + 3]] += w[i + 3];
    }
    for (; i < n; ++i) part[0][(bins[i] << 1) | y[i]] += w[i];
  } else {
    std::size_t k = 0;
    for (; k + 4 <= subset_size; k += 4) {
      for (std::size_t u = 0; u < 4; ++u) {
        const std::size_t i = subset[k + u];
        part[u][(bins[i] << 1) | y[i]] += w[i];
      }
    }
    for (; k < subset_size; ++k) {
      const std::size_t i = subset[k];
      part[0][(bins[i] << 1) | y[i]] += w[i];
    }
  }
  for (std::size_t j = 0; j < width; ++j) sums[j] = (part[0][j] + part[1][j]) + (part[2][j] + part[3][j]);
}

// The best two-way split of a feature's bins, bins <= t left and the others right: the smallest
// Z = 2 (sqrt(W+_L W-_L) + sqrt(W+_R W-_R)) over t = 0 .. bins - 2, and that t (the lowest of equals).
std::pair<double, int> split_z(const double* sums, int bin_count) {
  double total_pos = 0.0, total_neg = 0.0;
  for (int j = 0; j < bin_count; ++j) {
    total_neg += sums[2 * j];
    total_pos += sums[2 * j + 1];
  }
  double left_pos = 0.0, left_neg = 0.0, best = std::numeric_limits<double>::infinity();
  int best_t = 0;
  for (int t = 0; t + 1 < bin_count; ++t) {
    left_neg += sums[2 * t];
    left_pos += sums[2 * t + 1];
    const double z = 2.0 * (std::sqrt(left_pos * left_neg) +
                            std::sqrt(std::max(0.0, total_pos - left_pos) * std::max(0.0, total_neg - left_neg)));
    if (z < best) {
      best = z;
      best_t = t;
    }
  }
  return {best, best_t};
}

}  // namespace

std::vector<std::size_t> positives_first_order(const std::vector<int>& labels, const std::vector<std::size_t>& indices) {
  std::vector<std::size_t> order = indices;
  if (order.empty()) {
    order.resize(labels.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
  }
  std::stable_partition(order.begin(), order.end(), [&](std::size_t i) { return labels[i] == 1; });
  return order;
}

RealAdaBoost::RealAdaBoost(const BinnedMatrix& data, std::vector<int> labels, RealAdaBoostParams params)
    : data_(data), labels_(std::move(labels)), params_(params) {
  if (labels_.size() != data_.samples()) {
    throw Error("Real AdaBoost: " + std::to_string(labels_.size()) + " labels for " +
                std::to_string(data_.samples()) + " samples");
  }
  const auto positives = std::count(labels_.begin(), labels_.end(), 1);
  double counts[2] = {static_cast<double>(positives), static_cast<double>(labels_.size())};  // exact integers
  if (sharded()) {
    params_.shards->sum(counts, 2);
    if (params_.weight_trim > 0.0 || params_.histogram_subtraction) {
      throw Error("Real AdaBoost: weight trimming and histogram subtraction need one process (data-parallel "
                  "training over " + std::to_string(params_.shards->size()) + " ranks)");
    }
  }
  total_samples_ = static_cast<std::size_t>(counts[1]);
  if (counts[0] == 0.0 || counts[0] == counts[1]) {
    throw Error("Real AdaBoost: both positive and negative training samples are needed");
  }
  for (int label : labels_) {
    if (label != 0 && label != 1) throw Error("Real AdaBoost: labels must be 1 (person) or 0");
  }
  if (data_.features() == 0) throw Error("Real AdaBoost: no features");
  if (!(params_.weight_trim >= 0.0 && params_.weight_trim < 1.0)) {
    throw Error("Real AdaBoost: weight trim " + std::to_string(params_.weight_trim) + " is outside [0, 1)");
  }
  const double n = static_cast<double>(total_samples_);
  eps_ = params_.smoothing > 0.0 ? params_.smoothing : 1.0 / n;
  if (params_.depth < 1 || params_.depth > 4) {
    throw Error("Real AdaBoost: depth " + std::to_string(params_.depth) + " is outside 1..4");
  }
  if (!(params_.learning_rate > 0.0 && params_.learning_rate <= 1.0)) {
    throw Error("Real AdaBoost: learning rate " + std::to_string(params_.learning_rate) + " is outside (0, 1]");
  }
  threads_ = resolve_thread_count(params_.threads);
  positives_first_ = std::is_sorted(labels_.begin(), labels_.end(), [](int a, int b) { return a > b; });
  positives_ = static_cast<std::size_t>(positives);
  weights_.assign(labels_.size(), 1.0 / n);
  scores_.assign(labels_.size(), 0.0);
}

void RealAdaBoost::start_from_scores(const std::vector<double>& scores) {
  if (scores.size() != labels_.size()) {
    throw Error("Real AdaBoost: " + std::to_string(scores.size()) + " starting scores for " +
                std::to_string(labels_.size()) + " samples");
  }
  if (!weak_.empty()) throw Error("Real AdaBoost: starting scores are set before the first round");
  scores_ = scores;
  // exp(-y F) scaled by the largest exponent first, so that large scores cannot overflow.
  double largest = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < scores.size(); ++i) largest = std::max(largest, labels_[i] == 1 ? -scores[i] : scores[i]);
  if (sharded()) params_.shards->max(&largest, 1);
  double total = 0.0;
  for (std::size_t i = 0; i < scores.size(); ++i) {
    weights_[i] = std::exp((labels_[i] == 1 ? -scores[i] : scores[i]) - largest);
    total += weights_[i];
  }
  if (sharded()) params_.shards->sum(&total, 1);
  for (double& w : weights_) w /= total;
}

std::vector<std::size_t> RealAdaBoost::trimmed_samples() const {
  std::vector<std::size_t> order(weights_.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return weights_[a] > weights_[b]; });
  const double keep = 1.0 - params_.weight_trim;
  double mass = 0.0;
  std::size_t count = 0;
  while (count < order.size() && mass < keep) mass += weights_[order[count++]];
  order.resize(count);
  std::sort(order.begin(), order.end());
  return order;
}

double RealAdaBoost::table_z(const double* sums, bool split) const {
  const int bin_count = data_.scheme().count;
  if (split) return split_z(sums, bin_count).first;
  double z = 0.0;
  for (int j = 0; j < bin_count; ++j) z += std::sqrt(sums[2 * j] * sums[2 * j + 1]);
  return 2.0 * z;
}

RealAdaBoost::TableFit RealAdaBoost::fit_feature(std::size_t feature, double z, const std::vector<std::size_t>* subset,
                                                 const std::vector<std::uint8_t>& y, bool split) const {
  const int bin_count = data_.scheme().count;
  // Responses of the chosen feature, from the same samples as its histograms.
  double sums[2 * kMaxBins];
  feature_histogram(data_.feature(feature), y.data(), weights_.data(), data_.samples(),
                    subset == nullptr ? nullptr : subset->data(), subset == nullptr ? 0 : subset->size(), bin_count,
                    sums);
  return fit_sums(feature, z, sums, split);
}

RealAdaBoost::TableFit RealAdaBoost::fit_sums(std::size_t feature, double z, const double* sums, bool split) const {
  const int bin_count = data_.scheme().count;
  TableFit fit;
  fit.feature = feature;
  fit.z = z;
  fit.responses.resize(static_cast<std::size_t>(bin_count));
  if (split) {
    const int t = split_z(sums, bin_count).second;  // bins <= t go left (-1), the others right (+1)
    for (int j = 0; j < bin_count; ++j) fit.responses[static_cast<std::size_t>(j)] = j <= t ? -1.0 : 1.0;
    return fit;
  }
  for (int j = 0; j < bin_count; ++j) {
    fit.responses[static_cast<std::size_t>(j)] = 0.5 * std::log((sums[2 * j + 1] + eps_) / (sums[2 * j] + eps_));
  }
  return fit;
}

void RealAdaBoost::TableScan::features(std::size_t f0, std::size_t f1, double* best_z, std::size_t* best_f) const {
  const BinnedMatrix& data = booster.data_;
  const std::size_t n = data.samples(), features_count = data.features(), nodes = direct_of.size();
  const int bin_count = data.scheme().count;
  const std::size_t width = 2 * static_cast<std::size_t>(bin_count);
  const std::vector<double>& weights = booster.weights_;
  std::vector<double> sums(8 * nodes * width), difference(width);
  for (std::size_t k = 0; k < nodes; ++k) best_f[k] = f0;
  auto consider = [&](std::size_t f, std::size_t node, const double* s) {
    if (keep != nullptr) std::copy(s, s + width, keep->data() + (node * features_count + f) * width);
    const double z = booster.table_z(s, split);
    if (z < best_z[node]) {
      best_z[node] = z;
      best_f[node] = f;
    }
  };
  auto sums_of = [&](std::size_t k) { return sums.data() + k * width; };
  std::size_t f = f0;
  while (f < f1) {
    const int count = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(pass), f1 - f));
    const std::uint8_t* bins[8];
    double* out[8 * 8];
    for (int k = 0; k < count; ++k) bins[k] = data.feature(f + static_cast<std::size_t>(k));
    if (two_part && count >= 4) {
      const int whole = count >= 8 ? 8 : 4;
      for (int k = 0; k < whole; ++k) out[k] = sums_of(static_cast<std::size_t>(k));
      two_part_histograms(bins, whole, weights.data(), booster.positives_, n, bin_count, out);
      for (int k = 0; k < whole; ++k) consider(f + static_cast<std::size_t>(k), 0, out[k]);
      f += static_cast<std::size_t>(whole);
    } else if (two_part) {
      feature_histogram(data.feature(f), y.data(), weights.data(), n, nullptr, 0, bin_count, sums_of(0));
      consider(f, 0, sums_of(0));
      ++f;
    } else {
      for (std::size_t k = 0; k < static_cast<std::size_t>(count) * direct; ++k) out[k] = sums_of(k);
      node_histograms(bins, count, samples, bin_count, out);
      for (int k = 0; k < count; ++k) {
        const std::size_t fk = f + static_cast<std::size_t>(k);
        for (std::size_t node = 0; node < nodes; ++node) {
          if (derived == nullptr || derived->sibling[node] < 0) {
            consider(fk, node, out[static_cast<std::size_t>(k) * direct + direct_of[node]]);
            continue;
          }
          // parent - sibling; a difference within the rounding of the parent's sum (relative 1e-9) is 0:
          // an empty bin must stay empty, or a pure node's Z is no longer 0 and ties break at random.
          const double* parent =
              derived->parent_sums->data() + (static_cast<std::size_t>(derived->parent[node]) * features_count + fk) * width;
          const double* sibling =
              out[static_cast<std::size_t>(k) * direct + direct_of[static_cast<std::size_t>(derived->sibling[node])]];
          for (std::size_t j = 0; j < width; ++j) {
            const double d = parent[j] - sibling[j];
            difference[j] = d > 1e-9 * parent[j] ? d : 0.0;
          }
          consider(fk, node, difference.data());
        }
      }
      f += static_cast<std::size_t>(count);
    }
  }
}

std::vector<RealAdaBoost::TableFit> RealAdaBoost::best_tables(const std::vector<const std::vector<std::size_t>*>& members,
                                                              const std::vector<std::uint8_t>& y, bool split,
                                                              const Subtraction* derived, std::vector<double>* keep) const {
  const std::size_t n = data_.samples(), features = data_.features(), nodes = members.size();
  const int bin_count = data_.scheme().count;
  const std::size_t width = 2 * static_cast<std::size_t>(bin_count);
  // Nodes whose sums are taken (direct); with histogram subtraction the others are parent - sibling.
  std::vector<std::size_t> direct_of(nodes, 0);
  std::vector<const std::vector<std::size_t>*> direct_lists;
  for (std::size_t j = 0; j < nodes; ++j) {
    if (derived != nullptr && derived->sibling[j] >= 0) continue;
    direct_of[j] = direct_lists.size();
    direct_lists.push_back(members[j]);
  }
  const std::size_t direct = direct_lists.size();
  if (keep != nullptr) keep->resize(nodes * features * width);  // every entry is written below
  // The two-part sums apply to the whole sample set ordered positives first (members[0] null); every
  // other set of nodes takes the four-part sums of NodeSamples.
  const bool two_part = nodes == 1 && members[0] == nullptr && positives_first_;
  std::vector<std::size_t> all;
  std::vector<const std::vector<std::size_t>*> lists = members;
  if (nodes == 1 && members[0] == nullptr && !two_part) {
    all.resize(n);
    std::iota(all.begin(), all.end(), std::size_t{0});
    lists[0] = &all;
  }
  if (!two_part && direct == nodes) direct_lists = lists;
  NodeSamples samples = two_part ? NodeSamples({}, y, 0) : NodeSamples(direct_lists, y, n);
  if (!two_part) samples.gather_weights(weights_);
  // Features of one pass: eight two-part (4 tables of 64 doubles per feature: 16 KiB; four above 64
  // bins, whose tables take 256), or for the four-part sums (8 tables of 64 doubles per node and
  // feature: 4 KiB) the count that was fastest on the AMD EPYC of docs/performance.md, keeping the tables
  // within its 32 KiB first-level data cache: 4 for one node, 2 for 2-4 nodes, else 1.
  const int pass = two_part ? (bin_count > 64 ? 4 : 8) : bin_count > 64 || direct > 4 ? 1 : direct == 1 ? 4 : 2;
  // Best feature per chunk and node, then across chunks in chunk order (lowest index wins ties). Chunks
  // are made of whole blocks of four features, so every feature's sums are taken the same way whatever
  // the thread count: in two-part passes, except the last features % 4, which take the four-part sums
  // of feature_histogram.
  const std::size_t blocks = (features + 3) / 4;
  const int chunks = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threads_), blocks));
  std::vector<double> chunk_z(static_cast<std::size_t>(chunks) * nodes, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> chunk_feature(static_cast<std::size_t>(chunks) * nodes, 0);
  const std::size_t step = (blocks + static_cast<std::size_t>(chunks) - 1) / static_cast<std::size_t>(chunks);
  const TableScan scan{*this, y, split, derived, keep, samples, direct_of, direct, two_part, pass};
  parallel_chunks(blocks, chunks, [&](std::size_t block0, std::size_t block1) {
    const std::size_t chunk = block0 / step;
    scan.features(block0 * 4, std::min(features, block1 * 4), chunk_z.data() + chunk * nodes,
                  chunk_feature.data() + chunk * nodes);
  });
  std::vector<TableFit> fits;
  for (std::size_t node = 0; node < nodes; ++node) {
    std::size_t best = 0;
    for (std::size_t c = 1; c < static_cast<std::size_t>(chunks); ++c) {
      if (chunk_z[c * nodes + node] < chunk_z[best * nodes + node]) best = c;
    }
    fits.push_back(fit_feature(chunk_feature[best * nodes + node], chunk_z[best * nodes + node],
                               two_part ? nullptr : lists[node], y, split));
  }
  return fits;
}

std::vector<RealAdaBoost::TableFit> RealAdaBoost::best_tables_sharded(
    const std::vector<const std::vector<std::size_t>*>& members, const std::vector<std::uint8_t>& y, bool split) const {
  const std::size_t features = data_.features(), nodes = members.size();
  const std::size_t width = 2 * static_cast<std::size_t>(data_.scheme().count);
  const RowShards& shards = *params_.shards;
  std::vector<double> sums;  // [node][feature][2 * bins]: this rank's
  best_tables(members, y, split, nullptr, &sums);
  // Per node, this rank sums every rank's sums of its block of features (reduce-scatter) and finds the
  // block's best: the smallest Z, the lowest feature of equals.
  std::vector<double> candidates;  // per node: Z, feature
  for (std::size_t node = 0; node < nodes; ++node) {
    double* node_sums = sums.data() + node * features * width;
    // The block as named variables, not a structured binding: the lambda below captures them (clang 14 refuses
    // a captured binding in C++17).
    const std::pair<std::size_t, std::size_t> block = shards.sum_own_block(node_sums, features, width);
    const std::size_t f0 = block.first, f1 = block.second;
    std::vector<double> z(f1 - f0);
    parallel_chunks(z.size(), threads_, [&](std::size_t k0, std::size_t k1) {
      for (std::size_t k = k0; k < k1; ++k) z[k] = table_z(node_sums + (f0 + k) * width, split);
    });
    const auto best = std::min_element(z.begin(), z.end());
    candidates.push_back(best == z.end() ? std::numeric_limits<double>::infinity() : *best);
    candidates.push_back(static_cast<double>(f0 + static_cast<std::size_t>(best - z.begin())));
  }
  // The best of the blocks (rank order = feature order, so ties still go to the lowest feature), then the
  // winners' sums from the ranks that hold them.
  const std::vector<double> all = shards.gather(candidates);
  const auto ranks = static_cast<std::size_t>(shards.size());
  std::vector<std::size_t> winner(nodes, 0);
  for (std::size_t node = 0; node < nodes; ++node) {
    for (std::size_t r = 1; r < ranks; ++r) {
      if (all[(r * nodes + node) * 2] < all[(winner[node] * nodes + node) * 2]) winner[node] = r;
    }
  }
  std::vector<double> mine;
  for (std::size_t node = 0; node < nodes; ++node) {
    if (winner[node] != static_cast<std::size_t>(shards.rank())) continue;
    const auto feature = static_cast<std::size_t>(candidates[2 * node + 1]);
    const double* s = sums.data() + (node * features + feature) * width;
    mine.insert(mine.end(), s, s + width);
  }
  const std::vector<double> won = shards.gather(mine);  // rank order, each rank's nodes in order
  std::vector<TableFit> fits(nodes);
  std::size_t next = 0;
  for (std::size_t r = 0; r < ranks; ++r) {
    for (std::size_t node = 0; node < nodes; ++node) {
      if (winner[node] != r) continue;
      const double* c = all.data() + (r * nodes + node) * 2;
      fits[node] = fit_sums(static_cast<std::size_t>(c[1]), c[0], won.data() + next, split);
      next += width;
    }
  }
  return fits;
}

double RealAdaBoost::fit_table(const std::vector<std::size_t>& trimmed, const std::vector<std::uint8_t>& y,
                               WeakClassifier& weak, std::vector<double>& response) const {
  const std::vector<const std::vector<std::size_t>*> all{trimmed.empty() ? nullptr : &trimmed};
  TableFit fit = std::move((sharded() ? best_tables_sharded(all, y, false) : best_tables(all, y, false))[0]);
  weak.kind = WeakClassifier::Kind::Lut;
  weak.feature = static_cast<int>(fit.feature);
  for (double& r : fit.responses) r *= params_.learning_rate;
  weak.responses = std::move(fit.responses);
  const std::uint8_t* bins = data_.feature(fit.feature);
  for (std::size_t i = 0; i < response.size(); ++i) response[i] = weak.responses[bins[i]];
  return fit.z;
}

double RealAdaBoost::fit_tree_level(std::size_t k0, const std::vector<std::size_t>& trimmed,
                                    const std::vector<std::uint8_t>& y, std::vector<std::size_t>& node_of,
                                    LevelSums& sums, WeakClassifier& weak) const {
  const std::size_t n = node_of.size();
  const std::size_t first_leaf = weak.nodes.size() / 2;
  const std::size_t k1 = 2 * k0 + 1;  // the level is nodes k0 .. k1 - 1
  const bool inner = k0 < first_leaf;
  // The samples of each node that enter its histograms, ascending (trimmed ones stay out, as at
  // depth 1), and their weight.
  std::vector<std::vector<std::size_t>> members(k1 - k0);
  if (trimmed.empty()) {
    for (std::size_t i = 0; i < n; ++i) members[node_of[i] - k0].push_back(i);
  } else {
    for (std::size_t i : trimmed) members[node_of[i] - k0].push_back(i);
  }
  std::vector<std::size_t> fitted;
  std::vector<const std::vector<std::size_t>*> lists;
  std::vector<double> masses(k1 - k0, 0.0);
  for (std::size_t k = k0; k < k1; ++k) {
    for (std::size_t i : members[k - k0]) masses[k - k0] += weights_[i];
  }
  if (sharded()) params_.shards->sum(masses.data(), masses.size());
  for (std::size_t k = k0; k < k1; ++k) {
    const double mass = masses[k - k0];
    LutNode& node = weak.nodes[k];
    if (k > 0 && mass <= 1e-12) {
      // Nothing reaches it: a table of zeros (a leaf responds 0, an inner node sends everything left).
      node.feature = weak.nodes[(k - 1) / 2].feature;
      node.responses.assign(static_cast<std::size_t>(data_.scheme().count), inner ? -1.0 : 0.0);
    } else {
      fitted.push_back(k);
      lists.push_back(k == 0 && trimmed.empty() ? nullptr : &members[k - k0]);
    }
  }
  const std::vector<std::ptrdiff_t> parent_of_level = sums.parent_index;
  std::fill(sums.parent_index.begin(), sums.parent_index.end(), -1);  // set again below for this level's nodes
  double z = 0.0;
  if (!fitted.empty()) {
    // With subtraction, of two fitted children of a fitted parent the one with fewer samples is
    // counted and the other is parent - sibling.
    Subtraction sub;
    sub.parent_sums = &sums.parent_sums;
    sub.parent.assign(fitted.size(), -1);
    sub.sibling.assign(fitted.size(), -1);
    bool any = false;
    for (std::size_t j = 0; params_.histogram_subtraction && j + 1 < fitted.size(); ++j) {
      const std::size_t k = fitted[j];
      if (k % 2 == 0 || fitted[j + 1] != k + 1 || parent_of_level[(k - 1) / 2] < 0) continue;
      const std::size_t bigger = members[k - k0].size() >= members[k + 1 - k0].size() ? j : j + 1;
      sub.parent[bigger] = parent_of_level[(k - 1) / 2];
      sub.sibling[bigger] = static_cast<std::ptrdiff_t>(bigger == j ? j + 1 : j);
      any = true;
    }
    const bool keep = params_.histogram_subtraction && inner;
    std::vector<TableFit> fits = sharded() ? best_tables_sharded(lists, y, inner)
                                           : best_tables(lists, y, inner, any ? &sub : nullptr, keep ? &sums.level_sums : nullptr);
    if (keep) {
      for (std::size_t j = 0; j < fitted.size(); ++j) sums.parent_index[fitted[j]] = static_cast<std::ptrdiff_t>(j);
      sums.parent_sums.swap(sums.level_sums);
    }
    for (std::size_t j = 0; j < fitted.size(); ++j) {
      LutNode& node = weak.nodes[fitted[j]];
      node.feature = static_cast<int>(fits[j].feature);
      node.responses = std::move(fits[j].responses);
      if (!inner) z += fits[j].z;
    }
  }
  if (inner) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = node_of[i];
      const LutNode& node = weak.nodes[k];
      node_of[i] = 2 * k + (node.responses[data_.at(static_cast<std::size_t>(node.feature), i)] > 0.0 ? 2 : 1);
    }
  }
  return z;
}

double RealAdaBoost::fit_tree(const std::vector<std::size_t>& trimmed, const std::vector<std::uint8_t>& y,
                              WeakClassifier& weak, std::vector<double>& response) const {
  // Grown level by level; node_of[i] is the node sample i has reached.
  const std::size_t n = response.size();
  const std::size_t node_count = (std::size_t{1} << params_.depth) - 1;
  weak.kind = WeakClassifier::Kind::Tree;
  weak.nodes.resize(node_count);
  std::vector<std::size_t> node_of(n, 0);
  const std::size_t first_leaf = node_count / 2;
  // All the nodes of a level share one pass over the bins (node_histograms). Their members are fixed
  // before the level: routing a node moves its samples to the next level only.
  LevelSums sums;
  sums.parent_index.assign(node_count, -1);
  double z = 0.0;
  for (std::size_t k0 = 0; k0 < node_count; k0 = 2 * k0 + 1) z += fit_tree_level(k0, trimmed, y, node_of, sums, weak);
  // Leaves respond (shrunk); inner tables only route (+1 / -1).
  for (std::size_t k = first_leaf; k < node_count; ++k) {
    for (double& r : weak.nodes[k].responses) r *= params_.learning_rate;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const LutNode& leaf = weak.nodes[node_of[i]];
    response[i] = leaf.responses[data_.at(static_cast<std::size_t>(leaf.feature), i)];
  }
  weak.feature = weak.nodes[0].feature;
  return z;
}

double RealAdaBoost::reweight(const std::vector<double>& response) {
  // w_i exp(-y_i h(x_i)), then normalised; the scores take the response too.
  double total = 0.0;
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < response.size(); ++i) {
    weights_[i] *= std::exp(labels_[i] == 1 ? -response[i] : response[i]);
    total += weights_[i];
    scores_[i] += response[i];
    wrong += ((scores_[i] > 0.0) != (labels_[i] == 1)) ? 1 : 0;
  }
  double wrong_count = static_cast<double>(wrong);  // an exact integer
  if (sharded()) {
    double reduced[2] = {total, wrong_count};
    params_.shards->sum(reduced, 2);
    total = reduced[0];
    wrong_count = reduced[1];
  }
  for (double& w : weights_) w /= total;
  return wrong_count;
}

RealAdaBoostRound RealAdaBoost::next_round() {
  const std::size_t n = data_.samples();
  const std::vector<std::size_t> trimmed =
      params_.weight_trim > 0.0 ? trimmed_samples() : std::vector<std::size_t>{};
  std::vector<std::uint8_t> y(n);
  for (std::size_t i = 0; i < n; ++i) y[i] = static_cast<std::uint8_t>(labels_[i]);

  WeakClassifier weak;
  std::vector<double> response(n);  // the weak classifier's (shrunk) response per sample
  const double z = params_.depth <= 1 ? fit_table(trimmed, y, weak, response) : fit_tree(trimmed, y, weak, response);
  const double wrong_count = reweight(response);
  const int feature = weak.feature;
  weak_.push_back(std::move(weak));

  RealAdaBoostRound report;
  report.round = static_cast<int>(weak_.size());
  report.feature = feature;
  report.z = z;
  report.train_error = wrong_count / static_cast<double>(total_samples_);
  report.samples_used = trimmed.empty() ? total_samples_ : trimmed.size();
  return report;
}

}  // namespace rdsf
