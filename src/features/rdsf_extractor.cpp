#include "rdsf/features/rdsf_extractor.hpp"

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
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) *out++ = pair_value(h, i, j);
  }
}

std::vector<float> RdsfExtractor::compute(const cv::Mat1w& crop) const {
  std::vector<float> features(static_cast<std::size_t>(dimension()));
  compute(crop, features.data());
  return features;
}

}  // namespace rdsf
