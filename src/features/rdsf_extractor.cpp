#include "features/rdsf_extractor.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "core/error.hpp"

namespace rdsf {
namespace {

using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

}  // namespace

RdsfExtractor::RdsfExtractor(FeatureSpec spec) : spec_(spec) { spec_.validate(); }

int RdsfExtractor::bin_of(int depth_mm) const {
  if (depth_mm <= 0) return 0;
  return 1 + std::min(depth_mm / spec_.bin_width_mm, spec_.bin_count() - 2);
}

cv::Mat1f RdsfExtractor::cell_histograms(const cv::Mat1w& crop) const {
  if (crop.cols != spec_.window_width_px || crop.rows != spec_.window_height_px) {
    throw Error("RDSF: crop is " + std::to_string(crop.cols) + "x" + std::to_string(crop.rows) +
                ", the feature spec needs " + std::to_string(spec_.window_width_px) + "x" +
                std::to_string(spec_.window_height_px));
  }
  const int cell = spec_.cell_px;
  const float weight = 1.0f / static_cast<float>(cell * cell);
  cv::Mat1f histograms = cv::Mat1f::zeros(spec_.cell_count(), spec_.bin_count());
  for (int y = 0; y < crop.rows; ++y) {
    const std::uint16_t* row = crop.ptr<std::uint16_t>(y);
    const int cell_row = (y / cell) * spec_.cells_x();
    for (int x = 0; x < crop.cols; ++x) {
      histograms(cell_row + x / cell, bin_of(row[x])) += weight;
    }
  }
  return histograms;
}

void RdsfExtractor::compute(const cv::Mat1w& crop, float* out) const {
  const cv::Mat1f histograms = cell_histograms(crop);
  const int n = spec_.cell_count();
  const int bins = spec_.bin_count();
  RowMatrix roots(n, bins);
  for (int i = 0; i < n; ++i) {
    const float* h = histograms.ptr<float>(i);
    for (int b = 0; b < bins; ++b) roots(i, b) = std::sqrt(h[b]);
  }
  RowMatrix gram = RowMatrix::Zero(n, n);
  gram.selfadjointView<Eigen::Upper>().rankUpdate(roots);
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      *out++ = std::min(1.0f, std::max(0.0f, gram(i, j)));  // rounding can leave 1 + 1e-7
    }
  }
}

std::vector<float> RdsfExtractor::compute(const cv::Mat1w& crop) const {
  std::vector<float> features(static_cast<std::size_t>(dimension()));
  compute(crop, features.data());
  return features;
}

}  // namespace rdsf
