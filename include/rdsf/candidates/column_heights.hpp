#pragma once
// Per layer and per column, the longest vertical run of the layer's pixels, tolerating gaps.
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf {

struct ColumnRun {
  int top = -1;     ///< first row of the longest run, -1 when the column holds none of the layer
  int bottom = -1;  ///< last row of the longest run
  int length() const { return top < 0 ? 0 : bottom - top + 1; }
};

/// runs[layer_label][column] for every label 1..layer_count. A run goes on through gaps of at most `k` rows
/// without the layer's pixels; its length counts the gaps. Labels are ordered nearest first, so a gap with
/// pixels of nearer layers and no pixel of a farther one is something standing in front of the layer (a
/// table before a person's legs, with its shadow of missing readings): such an occlusion gap does not break
/// the run while it is at most occlusion_gap_px[label] rows (index 0 unused; an empty vector or 0 allows
/// none beyond `k`). A gap of missing readings only (no pixel of any layer: a hole the sensor left on the
/// layer, such as dark clothes or hair) does not break it while it is at most hole_gap_px[label] rows (the
/// same indexing; empty or 0: none beyond `k`).
std::vector<std::vector<ColumnRun>> column_runs(const cv::Mat1b& labels, int layer_count, int k,
                                                const std::vector<int>& occlusion_gap_px = {},
                                                const std::vector<int>& hole_gap_px = {});

}  // namespace rdsf
