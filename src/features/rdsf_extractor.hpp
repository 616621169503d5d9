#pragma once
// Relational depth similarity features (RDSF) of a 64x128 masked depth crop: the Bhattacharyya coefficient
// of the depth histograms of every pair of cells (see feature_spec.hpp for the exact definition).
//
// With s_i the element-wise square root of cell i's normalised histogram, the coefficient of (i, j) is the
// dot product s_i . s_j, so all 8128 values are the upper triangle of the Gram matrix S S^T (128 x 26
// matrix S), computed with Eigen.
#include <vector>

#include <opencv2/core.hpp>

#include "features/feature_spec.hpp"

namespace rdsf {

class RdsfExtractor {
 public:
  explicit RdsfExtractor(FeatureSpec spec = {});

  const FeatureSpec& spec() const { return spec_; }
  int dimension() const { return spec_.dimension(); }

  /// Histogram bin of a depth value (0 = no reading).
  int bin_of(int depth_mm) const;

  /// Writes dimension() values to `out`. `crop_depth_mm` must be window-sized (CV_16UC1); throws Error
  /// otherwise.
  void compute(const cv::Mat1w& crop_depth_mm, float* out) const;
  std::vector<float> compute(const cv::Mat1w& crop_depth_mm) const;

  /// The normalised histograms, one row per cell (cell_count x bin_count), for inspection and tests.
  cv::Mat1f cell_histograms(const cv::Mat1w& crop_depth_mm) const;

 private:
  FeatureSpec spec_;
};

}  // namespace rdsf
