#pragma once
// Parameters of the depth segmentation (thesis names). The thesis does not publish its values; these
// defaults were chosen on ../shared/realdata (people found, layers that separate a person from the wall
// behind) and are documented in docs/frame-analyser.md. Each member's option name, help, check and thesis
// value are declared once in segmentation_parameters() (core/parameter_table.hpp).
#include "rdsf/core/parameter_table.hpp"

namespace rdsf {

struct SegmentationParams {
  /// Scan every row_step-th row of the depth map for depth jumps.
  int row_step = 10;
  /// A jump between neighbouring pixels larger than this (mm) starts a depth candidate.
  int depth_threshold_mm = 150;
  /// The jump must hold: the next n pixels stay within range_threshold_mm of the pixel after the jump.
  int n = 5;
  /// See n.
  int range_threshold_mm = 60;
  /// Sorted depth candidates are averaged in runs that span at most this much depth (mm).
  int candidate_threshold_mm = 700;
  /// The first pixel of a scanned row counts as a depth jump (the left image border), so that an object cut
  /// by the left border is seeded like one cut by the right border (seeded by its own left edge). false:
  /// the thesis's scan (jumps between neighbouring pixels only).
  bool left_border_jump = true;
  /// Upper bound of k-means iterations; it stops earlier when no pixel changes layer.
  int max_iterations = 30;
};

/// The table of SegmentationParams: options, config keys, checks and thesis values.
const ParameterTable<SegmentationParams>& segmentation_parameters();

}  // namespace rdsf
