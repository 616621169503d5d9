#include "rdsf/features/rdsf_extractor.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace rdsf {

RdsfExtractor::RdsfExtractor(FeatureSpec spec) : builder_(spec) {}

cv::Mat1f RdsfExtractor::cell_histograms(const cv::Mat1w& crop) const {
  RootHistograms h;
  builder_.compute_all(crop, h);
  cv::Mat1f histograms(spec().region_count(), h.bins);
  for (int r = 0; r < histograms.rows; ++r) {
    const float* roots = h.dense_of(r);
    for (int b = 0; b < h.bins; ++b) histograms(r, b) = roots[b] * roots[b];
  }
  return histograms;
}

void RdsfExtractor::compute(const cv::Mat1w& crop, float* out) const {
  thread_local RootHistograms h;  // reused: no allocation per crop
  builder_.compute_all(crop, h);
  const int n = spec().region_count();
  const int bins = h.bins;
  // pair_value(h, i, j) for every i < j, column by column: for region j, the sums over its non-zero bins
  // k = 0, 1, ... for all i < j at once (sum_i = dense_i[b_0] * root_0, then += dense_i[b_k] * root_k: the
  // same operations in the same order as pair_value, hence the same bits), over the dense roots kept
  // bin-major so that the loops over i are contiguous (and vectorised). Feature (i, j) is at
  // i * n - i * (i + 1) / 2 + (j - i - 1).
  thread_local std::vector<float> by_bin, sums;
  thread_local std::vector<std::size_t> row_start;
  by_bin.resize(static_cast<std::size_t>(bins) * n);
  sums.resize(static_cast<std::size_t>(n));
  row_start.resize(static_cast<std::size_t>(n));
  for (int r = 0; r < n; ++r) {
    const float* dense = h.dense_of(r);
    for (int b = 0; b < bins; ++b) by_bin[static_cast<std::size_t>(b) * n + r] = dense[b];
    row_start[static_cast<std::size_t>(r)] =
        static_cast<std::size_t>(r) * n - static_cast<std::size_t>(r) * (r + 1) / 2 - static_cast<std::size_t>(r) - 1;
  }
  float* const sum = sums.data();
  for (int j = 1; j < n; ++j) {
    const std::size_t base = static_cast<std::size_t>(j) * bins;
    const std::uint8_t* bin = h.nz_bin.data() + base;
    const float* root = h.nz_root.data() + base;
    const int nonzero = h.nz_count[static_cast<std::size_t>(j)];
    if (nonzero == 0) {
      std::fill(sum, sum + j, 0.0f);
    } else {
      const float* first = by_bin.data() + static_cast<std::size_t>(bin[0]) * n;
      const float r0 = root[0];
      for (int i = 0; i < j; ++i) sum[i] = first[i] * r0;  // 0 + x is x (x >= 0): pair_value's first term
      for (int k = 1; k < nonzero; ++k) {
        const float* dense = by_bin.data() + static_cast<std::size_t>(bin[k]) * n;
        const float rk = root[k];
        for (int i = 0; i < j; ++i) sum[i] += dense[i] * rk;
      }
    }
    for (int i = 0; i < j; ++i) out[row_start[static_cast<std::size_t>(i)] + j] = sum[i] > 1.0f ? 1.0f : sum[i];
  }
}

std::vector<float> RdsfExtractor::compute(const cv::Mat1w& crop) const {
  std::vector<float> features(static_cast<std::size_t>(dimension()));
  compute(crop, features.data());
  return features;
}

}  // namespace rdsf
