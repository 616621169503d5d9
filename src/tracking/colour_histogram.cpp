#include "rdsf/tracking/colour_histogram.hpp"

#include <algorithm>
#include <cmath>

#include "rdsf/core/error.hpp"

namespace rdsf {

ColourHistogram ColourHistogram::of(const cv::Mat3b& bgr_crop, const cv::Mat1w& depth_crop, int bins_per_channel) {
  ColourHistogram histogram;
  histogram.bins_per_channel = bins_per_channel;
  if (bgr_crop.empty()) return histogram;
  if (bgr_crop.size() != depth_crop.size()) throw Error("colour histogram: colour and depth crops differ in size");
  if (bins_per_channel < 1 || bins_per_channel > 256) throw Error("colour histogram: bins per channel must be 1..256");
  const int b = bins_per_channel;
  std::vector<float> counts(static_cast<std::size_t>(b * b * b), 0.0f);
  int pixels = 0;
  for (int y = 0; y < bgr_crop.rows; ++y) {
    const cv::Vec3b* colour = bgr_crop.ptr<cv::Vec3b>(y);
    const std::uint16_t* depth = depth_crop.ptr<std::uint16_t>(y);
    for (int x = 0; x < bgr_crop.cols; ++x) {
      if (depth[x] == 0) continue;
      const int i = (colour[x][0] * b / 256) * b * b + (colour[x][1] * b / 256) * b + colour[x][2] * b / 256;
      counts[static_cast<std::size_t>(i)] += 1.0f;
      ++pixels;
    }
  }
  if (pixels == 0) return histogram;
  for (float& c : counts) c /= static_cast<float>(pixels);
  histogram.values = std::move(counts);
  return histogram;
}

double bhattacharyya_coefficient(const ColourHistogram& a, const ColourHistogram& b) {
  if (a.empty() || b.empty()) return 0.0;
  if (a.values.size() != b.values.size()) throw Error("colour histograms of different bin counts compared");
  double sum = 0;
  for (std::size_t i = 0; i < a.values.size(); ++i) sum += std::sqrt(static_cast<double>(a.values[i]) * b.values[i]);
  return std::min(1.0, sum);
}

double bhattacharyya_distance(const ColourHistogram& a, const ColourHistogram& b) {
  return std::sqrt(std::max(0.0, 1.0 - bhattacharyya_coefficient(a, b)));
}

}  // namespace rdsf
