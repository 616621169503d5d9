#pragma once
// Some of a feature spec's features, computed without the others: the histograms of only the regions the
// chosen pairs name, then only those pairs. A 100-round model reads at most 100 of the 8128 "rdsf" values;
// scoring it needs those alone. The values are bit for bit those of RdsfExtractor::compute (both go
// through RegionHistogramBuilder and pair_value).
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/features/feature_spec.hpp"
#include "rdsf/features/region_histograms.hpp"

namespace rdsf {

class FeatureSubset {
 public:
  /// `features`: indices into the spec's vector, in any order, repeats allowed. Throws Error on an index
  /// outside [0, dimension()).
  FeatureSubset(const FeatureSpec& spec, const std::vector<int>& features);

  const FeatureSpec& spec() const { return builder_.spec(); }
  /// The chosen features, ascending and without repeats: value k of compute() is feature features()[k].
  const std::vector<int>& features() const { return features_; }
  int size() const { return static_cast<int>(features_.size()); }
  /// Position of `feature` in features(), or -1.
  int position(int feature) const;
  /// Regions whose histograms compute() needs.
  int region_count() const { return static_cast<int>(regions_.size()); }

  /// Writes size() values to `out`; safe to call from several threads at once.
  void compute(const cv::Mat1w& crop_depth_mm, float* out) const;

 private:
  RegionHistogramBuilder builder_;
  std::vector<int> features_;
  std::vector<int> regions_;                   ///< ascending
  std::vector<std::pair<int, int>> slots_;     ///< per feature: slots of its regions i < j
};

}  // namespace rdsf
