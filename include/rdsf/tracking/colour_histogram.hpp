#pragma once
// The appearance of a tracked person: a normalised colour histogram of the masked colour crop (only the
// pixels of the candidate's depth layer), compared with the Bhattacharyya distance.
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf {

struct ColourHistogram {
  /// bins_per_channel^3 values over (B, G, R), summing to 1; empty when there was no colour or no pixel.
  std::vector<float> values;
  int bins_per_channel = 8;

  bool empty() const { return values.empty(); }

  /// Histogram of the pixels of `bgr_crop` where `depth_crop` has a reading (the layer mask).
  static ColourHistogram of(const cv::Mat3b& bgr_crop, const cv::Mat1w& depth_crop, int bins_per_channel = 8);
};

/// Bhattacharyya coefficient sum_i sqrt(p_i q_i) in [0, 1] (0 when either histogram is empty).
double bhattacharyya_coefficient(const ColourHistogram& a, const ColourHistogram& b);
/// Bhattacharyya distance sqrt(1 - coefficient) in [0, 1], the form cv::compareHist uses.
double bhattacharyya_distance(const ColourHistogram& a, const ColourHistogram& b);

}  // namespace rdsf
