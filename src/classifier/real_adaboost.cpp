#include "classifier/real_adaboost.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "classifier/parallel_chunks.hpp"
#include "core/error.hpp"

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
  threads_ = resolve_thread_count(params_.threads);
  positives_first_ = std::is_sorted(labels_.begin(), labels_.end(), [](int a, int b) { return a > b; });
  positives_ = static_cast<std::size_t>(positives);
  weights_.assign(labels_.size(), 1.0 / n);
  scores_.assign(labels_.size(), 0.0);
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

RealAdaBoostRound RealAdaBoost::next_round() {
  const std::size_t n = data_.samples(), features = data_.features();
  const int bin_count = data_.scheme().count;
  const std::vector<std::size_t> subset =
      params_.weight_trim > 0.0 ? trimmed_samples() : std::vector<std::size_t>{};
  std::vector<std::uint8_t> y(n);
  for (std::size_t i = 0; i < n; ++i) y[i] = static_cast<std::uint8_t>(labels_[i]);

  // Best feature per chunk, then across chunks in chunk order (lowest index wins ties). Chunks are made of
  // whole blocks of four features, so every feature's sums are taken the same way whatever the thread count.
  const std::size_t blocks = (features + 3) / 4;
  const int chunks = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threads_), blocks));
  std::vector<double> chunk_z(static_cast<std::size_t>(chunks), std::numeric_limits<double>::infinity());
  std::vector<std::size_t> chunk_feature(static_cast<std::size_t>(chunks), 0);
  const std::size_t step = (blocks + static_cast<std::size_t>(chunks) - 1) / static_cast<std::size_t>(chunks);
  parallel_chunks(blocks, chunks, [&](std::size_t block0, std::size_t block1) {
    const std::size_t chunk = block0 / step;
    const std::size_t f0 = block0 * 4, f1 = std::min(features, block1 * 4);
    double sums[4][2 * kMaxBins];
    double best_z = std::numeric_limits<double>::infinity();
    std::size_t best_f = f0;
    auto consider = [&](std::size_t f, const double* s) {
      double z = 0.0;
      for (int j = 0; j < bin_count; ++j) z += std::sqrt(s[2 * j] * s[2 * j + 1]);
      z *= 2.0;
      if (z < best_z) {
        best_z = z;
        best_f = f;
      }
    };
    std::size_t f = f0;
    if (subset.empty() && positives_first_) {
      for (; f + 4 <= f1; f += 4) {
        const std::uint8_t* const bins4[4] = {data_.feature(f), data_.feature(f + 1), data_.feature(f + 2),
                                              data_.feature(f + 3)};
        double* const sums4[4] = {sums[0], sums[1], sums[2], sums[3]};
        four_feature_histograms(bins4, weights_.data(), positives_, n, bin_count, sums4);
        for (std::size_t k = 0; k < 4; ++k) consider(f + k, sums[k]);
      }
    }
    for (; f < f1; ++f) {
      feature_histogram(data_.feature(f), y.data(), weights_.data(), n, subset.empty() ? nullptr : subset.data(),
                        subset.size(), bin_count, sums[0]);
      consider(f, sums[0]);
    }
    chunk_z[chunk] = best_z;
    chunk_feature[chunk] = best_f;
  });
  std::size_t best = 0;
  for (std::size_t c = 1; c < chunk_z.size(); ++c) {
    if (chunk_z[c] < chunk_z[best]) best = c;
  }
  const std::size_t feature = chunk_feature[best];

  // Responses of the chosen feature, from all samples (trimmed or not, as the histograms were).
  double sums[2 * kMaxBins];
  feature_histogram(data_.feature(feature), y.data(), weights_.data(), n, subset.empty() ? nullptr : subset.data(),
                    subset.size(), bin_count, sums);
  WeakClassifier weak;
  weak.kind = WeakClassifier::Kind::Lut;
  weak.feature = static_cast<int>(feature);
  weak.responses.resize(static_cast<std::size_t>(bin_count));
  for (int j = 0; j < bin_count; ++j) {
    weak.responses[static_cast<std::size_t>(j)] = 0.5 * std::log((sums[2 * j + 1] + eps_) / (sums[2 * j] + eps_));
  }

  // Reweighting: w_i exp(-y_i h(x_i)), then normalise.
  std::vector<double> factor_pos(static_cast<std::size_t>(bin_count)), factor_neg(factor_pos.size());
  for (std::size_t j = 0; j < factor_pos.size(); ++j) {
    factor_pos[j] = std::exp(-weak.responses[j]);
    factor_neg[j] = std::exp(weak.responses[j]);
  }
  const std::uint8_t* bins = data_.feature(feature);
  double total = 0.0;
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t b = bins[i];
    weights_[i] *= labels_[i] == 1 ? factor_pos[b] : factor_neg[b];
    total += weights_[i];
    scores_[i] += weak.responses[b];
    wrong += ((scores_[i] > 0.0) != (labels_[i] == 1)) ? 1 : 0;
  }
  for (double& w : weights_) w /= total;
  weak_.push_back(std::move(weak));

  RealAdaBoostRound report;
  report.round = static_cast<int>(weak_.size());
  report.feature = static_cast<int>(feature);
  report.z = chunk_z[best];
  report.train_error = static_cast<double>(wrong) / static_cast<double>(n);
  report.samples_used = subset.empty() ? n : subset.size();
  return report;
}

}  // namespace rdsf
