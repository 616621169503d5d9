#pragma once
// Summary statistics of a depth image, used to compare synthetic frames with real Kinect frames:
// how much of the image has a reading, the spread of the readings, how often a depth edge passes
// through missing readings (the Kinect's shadow beside every near object), and how the missing readings
// lie: few wide holes (shadows, dark objects) or many specks.
#include <opencv2/core.hpp>

namespace rdsf::synth {

struct DepthStatistics {
  double valid_fraction = 0;  ///< pixels with a reading (non-zero) / all pixels
  double p5_mm = 0;           ///< 5th percentile of the readings (0 when there are none)
  double p50_mm = 0;          ///< median of the readings
  double p95_mm = 0;          ///< 95th percentile of the readings
  /// Depth edges along rows that pass through missing readings / all depth edges along rows. A depth edge
  /// is a pair of readings in one row, at most edge_max_gap_px apart with only zeros between them, whose
  /// depths differ by more than edge_jump_mm and by more than 10%. 0 when there are no edges.
  double edge_hole_fraction = 0;
  long long edges = 0;  ///< the number of depth edges counted
  /// Runs of missing readings along rows (a run: consecutive zeros of one row), per image row.
  double hole_runs_per_row = 0;
  /// Runs of missing readings one pixel long / all runs (0 when there are none): specks.
  double single_pixel_hole_share = 0;
};

/// The statistics of `depth_mm` (CV_16UC1, millimetres, 0 = no reading).
DepthStatistics depth_statistics(const cv::Mat1w& depth_mm, int edge_jump_mm = 300, int edge_max_gap_px = 16);

}  // namespace rdsf::synth
