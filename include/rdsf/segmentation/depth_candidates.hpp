#pragma once
// Step 1 of the segmentation: depth candidates from a sparse row scan.
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/segmentation/segmentation_params.hpp"

namespace rdsf {

/// Scans every row_step-th row (starting at row 0) left to right. Pixel j is a depth candidate when
/// |d[j] - d[j-1]| > depth_threshold_mm and d[j+1..j+n] all lie within range_threshold_mm of d[j] (a jump
/// that holds). With left_border_jump the first pixel of a row counts as a jump too (the image border), so that
/// an object cut by the left border is seeded. Returns the candidate depths (mm) in scan order; 0 stands for a jump into "no reading".
std::vector<int> scan_depth_candidates(const cv::Mat1w& depth_mm, const SegmentationParams& params);

/// The same scan over one row of `width` depths, appending its candidates to `out` in scan order. Jumps are
/// looked for eight pixels at a time (SSE2: |a - b| = sat(a - b) | sat(b - a) > depth_threshold_mm) and only
/// the pixels after a jump are tested for holding; parameters outside 0 <= depth_threshold_mm < 65535, n >= 0
/// take the pixel-by-pixel loop.
void scan_depth_candidate_row(const std::uint16_t* row, int width, const SegmentationParams& params,
                              std::vector<int>& out);

/// Sorts the raw candidates, merges all zeros into one, and averages runs of sorted candidates that span
/// at most candidate_threshold_mm (a run starts at its smallest value). Returns the merged depths in
/// ascending order; a 0, when present, comes first and stands for "no reading".
std::vector<double> merge_depth_candidates(std::vector<int> raw, const SegmentationParams& params);

}  // namespace rdsf
