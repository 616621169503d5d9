#include "rdsf/classifier/real_adaboost.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "rdsf/classifier/parallel_chunks.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {
namespace {

constexpr int kMaxBins = 256;

// Per-bin weight sums of one feature: sums[2 * bin + y] (y = 1 person, 0 not). Four partial tables break
// the dependency between consecutive samples that fall into the same bin.
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

// Per-bin weight sums of four features at once when the samples are ordered positives first
// ([0, positives) have y = 1): the weight of a sample is loaded once for the four features, and two partial
// tables per feature break the chains of consecutive samples in the same bin (RDSF values crowd at 0 and 1).
void four_feature_histograms(const std::uint8_t* const bins[4], const double* w, std::size_t positives,
                             std::size_t n, int bin_count, double* const sums[4]) {
  double part[2][4][2 * kMaxBins];
  const std::size_t width = static_cast<std::size_t>(2 * bin_count);
  for (auto& a : part) {
    for (auto& b : a) std::fill(b, b + width, 0.0);
  }
  const std::uint8_t *b0 = bins[0], *b1 = bins[1], *b2 = bins[2], *b3 = bins[3];
  for (int y = 1; y >= 0; --y) {
    const std::size_t begin = y == 1 ? 0 : positives, end = y == 1 ? positives : n;
    std::size_t i = begin;
    for (; i + 2 <= end; i += 2) {
      const double wa = w[i], wb = w[i + 1];
      part[0][0][(b0[i] << 1) | y] += wa;
      part[0][1][(b1[i] << 1) | y] += wa;
      part[0][2][(b2[i] << 1) | y] += wa;
      part[0][3][(b3[i] << 1) | y] += wa;
      part[1][0][(b0[i + 1] << 1) | y] += wb;
      part[1][1][(b1[i + 1] << 1) | y] += wb;
      part[1][2][(b2[i + 1] << 1) | y] += wb;
      part[1][3][(b3[i + 1] << 1) | y] += wb;
    }
    for (; i < end; ++i) {
      part[0][0][(b0[i] << 1) | y] += w[i];
      part[0][1][(b1[i] << 1) | y] += w[i];
      part[0][2][(b2[i] << 1) | y] += w[i];
      part[0][3][(b3[i] << 1) | y] += w[i];
    }
  }
  for (int f = 0; f < 4; ++f) {
    for (std::size_t j = 0; j < width; ++j) sums[f][j] = part[0][f][j] + part[1][f][j];
  }
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
  if (positives == 0 || positives == static_cast<long>(labels_.size())) {
    throw Error("Real AdaBoost: both positive and negative training samples are needed");
  }
  for (int label : labels_) {
    if (label != 0 && label != 1) throw Error("Real AdaBoost: labels must be 1 (person) or 0");
  }
  if (data_.features() == 0) throw Error("Real AdaBoost: no features");
  if (!(params_.weight_trim >= 0.0 && params_.weight_trim < 1.0)) {
    throw Error("Real AdaBoost: weight trim " + std::to_string(params_.weight_trim) + " is outside [0, 1)");
  }
  const double n = static_cast<double>(labels_.size());
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
  double total = 0.0;
  for (std::size_t i = 0; i < scores.size(); ++i) {
    weights_[i] = std::exp((labels_[i] == 1 ? -scores[i] : scores[i]) - largest);
    total += weights_[i];
  }
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

RealAdaBoost::TableFit RealAdaBoost::best_table(const std::vector<std::size_t>* subset,
                                                const std::vector<std::uint8_t>& y, bool split) const {
  const std::size_t n = data_.samples(), features = data_.features();
  const int bin_count = data_.scheme().count;
  // Best feature per chunk, then across chunks in chunk order (lowest index wins ties). Chunks are made of
  // whole blocks of four features, so every feature's sums are taken the same way whatever the thread count.
  const std::size_t blocks = (features + 3) / 4;
  const int chunks = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threads_), blocks));
  std::vector<double> chunk_z(static_cast<std::size_t>(chunks), std::numeric_limits<double>::infinity());
  std::vector<std::size_t> chunk_feature(static_cast<std::size_t>(chunks), 0);
  const std::size_t step = (blocks + static_cast<std::size_t>(chunks) - 1) / static_cast<std::size_t>(chunks);
  const std::size_t* subset_data = subset == nullptr ? nullptr : subset->data();
  const std::size_t subset_size = subset == nullptr ? 0 : subset->size();
  parallel_chunks(blocks, chunks, [&](std::size_t block0, std::size_t block1) {
    const std::size_t chunk = block0 / step;
    const std::size_t f0 = block0 * 4, f1 = std::min(features, block1 * 4);
    double sums[4][2 * kMaxBins];
    double best_z = std::numeric_limits<double>::infinity();
    std::size_t best_f = f0;
    auto consider = [&](std::size_t f, const double* s) {
      double z = 0.0;
      if (split) {
        z = split_z(s, bin_count).first;
      } else {
        for (int j = 0; j < bin_count; ++j) z += std::sqrt(s[2 * j] * s[2 * j + 1]);
        z *= 2.0;
      }
      if (z < best_z) {
        best_z = z;
        best_f = f;
      }
    };
    std::size_t f = f0;
    if (subset == nullptr && positives_first_) {
      for (; f + 4 <= f1; f += 4) {
        const std::uint8_t* const bins4[4] = {data_.feature(f), data_.feature(f + 1), data_.feature(f + 2),
                                              data_.feature(f + 3)};
        double* const sums4[4] = {sums[0], sums[1], sums[2], sums[3]};
        four_feature_histograms(bins4, weights_.data(), positives_, n, bin_count, sums4);
        for (std::size_t k = 0; k < 4; ++k) consider(f + k, sums[k]);
      }
    }
    for (; f < f1; ++f) {
      feature_histogram(data_.feature(f), y.data(), weights_.data(), n, subset_data, subset_size, bin_count, sums[0]);
      consider(f, sums[0]);
    }
    chunk_z[chunk] = best_z;
    chunk_feature[chunk] = best_f;
  });
  std::size_t best = 0;
  for (std::size_t c = 1; c < chunk_z.size(); ++c) {
    if (chunk_z[c] < chunk_z[best]) best = c;
  }
  TableFit fit;
  fit.feature = chunk_feature[best];
  fit.z = chunk_z[best];
  // Responses of the chosen feature, from the same samples as its histograms.
  double sums[2 * kMaxBins];
  feature_histogram(data_.feature(fit.feature), y.data(), weights_.data(), n, subset_data, subset_size, bin_count,
                    sums);
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

RealAdaBoostRound RealAdaBoost::next_round() {
  const std::size_t n = data_.samples();
  const std::vector<std::size_t> trimmed =
      params_.weight_trim > 0.0 ? trimmed_samples() : std::vector<std::size_t>{};
  std::vector<std::uint8_t> y(n);
  for (std::size_t i = 0; i < n; ++i) y[i] = static_cast<std::uint8_t>(labels_[i]);
  const double nu = params_.learning_rate;

  WeakClassifier weak;
  std::vector<double> response(n);  // the weak classifier's (shrunk) response per sample
  double z = 0.0;
  if (params_.depth <= 1) {
    TableFit fit = best_table(trimmed.empty() ? nullptr : &trimmed, y, false);
    weak.kind = WeakClassifier::Kind::Lut;
    weak.feature = static_cast<int>(fit.feature);
    for (double& r : fit.responses) r *= nu;
    weak.responses = std::move(fit.responses);
    const std::uint8_t* bins = data_.feature(fit.feature);
    for (std::size_t i = 0; i < n; ++i) response[i] = weak.responses[bins[i]];
    z = fit.z;
  } else {
    // Grown level by level; node_of[i] is the node sample i has reached.
    const std::size_t node_count = (std::size_t{1} << params_.depth) - 1;
    weak.kind = WeakClassifier::Kind::Tree;
    weak.nodes.resize(node_count);
    std::vector<std::size_t> node_of(n, 0);
    const std::size_t first_leaf = node_count / 2;
    for (std::size_t k = 0; k < node_count; ++k) {
      // The samples of node k that enter its histograms (trimmed ones stay out, as at depth 1).
      std::vector<std::size_t> members;
      double mass = 0.0;
      if (trimmed.empty()) {
        for (std::size_t i = 0; i < n; ++i) {
          if (node_of[i] == k) members.push_back(i);
        }
      } else {
        for (std::size_t i : trimmed) {
          if (node_of[i] == k) members.push_back(i);
        }
      }
      for (std::size_t i : members) mass += weights_[i];
      LutNode& node = weak.nodes[k];
      if (k > 0 && mass <= 1e-12) {
        // Nothing reaches it: a table of zeros (a leaf responds 0, an inner node sends everything left).
        node.feature = weak.nodes[(k - 1) / 2].feature;
        node.responses.assign(static_cast<std::size_t>(data_.scheme().count), k < first_leaf ? -1.0 : 0.0);
      } else {
        const TableFit fit = best_table(k == 0 && trimmed.empty() ? nullptr : &members, y, k < first_leaf);
        node.feature = static_cast<int>(fit.feature);
        node.responses = fit.responses;
        if (k >= first_leaf) z += fit.z;
      }
      if (k < first_leaf) {
        const std::uint8_t* bins = data_.feature(static_cast<std::size_t>(node.feature));
        for (std::size_t i = 0; i < n; ++i) {
          if (node_of[i] == k) node_of[i] = 2 * k + (node.responses[bins[i]] > 0.0 ? 2 : 1);
        }
      }
    }
    // Leaves respond (shrunk); inner tables only route (+1 / -1).
    for (std::size_t k = first_leaf; k < node_count; ++k) {
      for (double& r : weak.nodes[k].responses) r *= nu;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const LutNode& leaf = weak.nodes[node_of[i]];
      response[i] = leaf.responses[data_.at(static_cast<std::size_t>(leaf.feature), i)];
    }
    weak.feature = weak.nodes[0].feature;
  }

  // Reweighting: w_i exp(-y_i h(x_i)), then normalise.
  double total = 0.0;
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < n; ++i) {
    weights_[i] *= std::exp(labels_[i] == 1 ? -response[i] : response[i]);
    total += weights_[i];
    scores_[i] += response[i];
    wrong += ((scores_[i] > 0.0) != (labels_[i] == 1)) ? 1 : 0;
  }
  for (double& w : weights_) w /= total;
  const int feature = weak.feature;
  weak_.push_back(std::move(weak));

  RealAdaBoostRound report;
  report.round = static_cast<int>(weak_.size());
  report.feature = feature;
  report.z = z;
  report.train_error = static_cast<double>(wrong) / static_cast<double>(n);
  report.samples_used = trimmed.empty() ? n : trimmed.size();
  return report;
}

}  // namespace rdsf
