#pragma once
// Relational depth similarity features (RDSF) of a 64x128 masked depth crop: the Bhattacharyya coefficient
// of the depth histograms of every pair of regions (cells for "rdsf", squares for "rdsf-rect"; see
// feature_spec.hpp for the exact definition and region_histograms.hpp for how they are computed).
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/features/feature_spec.hpp"
#include "rdsf/features/region_histograms.hpp"

namespace rdsf {

class RdsfExtractor {
 public:
  explicit RdsfExtractor(FeatureSpec spec = {});

  const FeatureSpec& spec() const { return builder_.spec(); }
  int dimension() const { return spec().dimension(); }

  /// Histogram bin of a depth value (0 = no reading).
  int bin_of(int depth_mm) const { return builder_.bin_of(depth_mm); }

  /// Writes dimension() values to `out`. `crop_depth_mm` must be window-sized (CV_16UC1); throws Error
  /// otherwise. Safe to call from several threads at once.
  void compute(const cv::Mat1w& crop_depth_mm, float* out) const;
  std::vector<float> compute(const cv::Mat1w& crop_depth_mm) const;

  /// The normalised histograms p_b, one row per region (region_count x bin_count), for inspection and tests.
  cv::Mat1f cell_histograms(const cv::Mat1w& crop_depth_mm) const;

 private:
  RegionHistogramBuilder builder_;
};

}  // namespace rdsf
