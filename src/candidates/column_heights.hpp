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

/// runs[layer_label][column] for every label 1..layer_count in one pass over the label image. A run goes
/// on through gaps of at most `k` rows without the layer's pixels; its length counts the gaps.
std::vector<std::vector<ColumnRun>> column_runs(const cv::Mat1b& labels, int layer_count, int k);

}  // namespace rdsf
