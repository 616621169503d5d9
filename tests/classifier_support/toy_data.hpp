#pragma once
// Small feature matrices for the classifier tests: uniform random RDSF-sized rows (8128 values in
// [0, 1]) whose label is decided by one or a few features.
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf::test {

struct ToyData {
  cv::Mat1f rows;
  std::vector<int> labels;
};

/// Label 1 exactly when feature `feature` > 0.5 (a bin edge of the default 64-bin scheme): separable by
/// one look-up table.
inline ToyData separable_toy(int samples, int feature, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  ToyData d;
  d.rows.create(samples, 8128);
  for (int r = 0; r < samples; ++r) {
    for (int c = 0; c < 8128; ++c) d.rows(r, c) = uniform(rng);
    d.labels.push_back(d.rows(r, feature) > 0.5f ? 1 : 0);
  }
  return d;
}

/// A noisy problem: the label follows the sum of a few features plus noise (not separable).
inline ToyData noisy_toy(int samples, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::normal_distribution<float> noise(0.0f, 0.35f);
  ToyData d;
  d.rows.create(samples, 8128);
  for (int r = 0; r < samples; ++r) {
    for (int c = 0; c < 8128; ++c) d.rows(r, c) = uniform(rng);
    const float signal = d.rows(r, 10) + d.rows(r, 2000) - d.rows(r, 5000) + noise(rng);
    d.labels.push_back(signal > 0.5f ? 1 : 0);
  }
  return d;
}

/// Fills row r of `rows` the way RDSF values crowd: u * u (near 0), one value in seven exactly 1, and
/// every fifth feature sqrt(u) (higher) when `label` is 1 (the Real AdaBoost reference tests' data).
inline void crowded_row(std::mt19937& rng, cv::Mat1f& rows, int r, int label) {
  for (int f = 0; f < rows.cols; ++f) {
    const double u = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
    const double shifted = (f % 5 == 0 && label == 1) ? std::sqrt(u) : u * u;
    rows(r, f) = static_cast<float>(rng() % 7 == 0 ? 1.0 : shifted);
  }
}

}  // namespace rdsf::test
