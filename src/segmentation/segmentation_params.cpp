#include "rdsf/segmentation/segmentation_params.hpp"

namespace rdsf {

const ParameterTable<SegmentationParams>& segmentation_parameters() {
  using P = SegmentationParams;
  static const ParameterTable<P> table = {
      parameter("row-step", &P::row_step, "scan every N-th row for depth jumps", Range::at_least(1)),
      parameter("depth-threshold", &P::depth_threshold_mm, "a depth jump larger than this (mm) starts a depth candidate",
                Range::at_least(0)),
      parameter("n", &P::n, "pixels after the jump that must stay within --range-threshold", Range::at_least(1)),
      parameter("range-threshold", &P::range_threshold_mm, "tolerance (mm) of the n pixels after a jump",
                Range::at_least(0)),
      parameter("candidate-threshold", &P::candidate_threshold_mm,
                "sorted depth candidates are averaged in runs spanning at most this (mm)", Range::at_least(0)),
      parameter("kmeans-iterations", &P::max_iterations, "upper bound of k-means iterations", Range::at_least(1)),
      parameter("left-border-jump", &P::left_border_jump, "the left image border counts as a depth jump; 0 = thesis",
                {}, std::optional<bool>(false)),
  };
  return table;
}

}  // namespace rdsf
