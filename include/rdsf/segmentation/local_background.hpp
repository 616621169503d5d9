#pragma once
// A per-frame stand-in for a background model (issue 34): what lies behind each pixel along its row, from
// the frame alone, so that a person standing within half a metre of a wall, a cupboard or a chair back
// (one depth layer with it) is in front of something even for a moving camera or a room never recorded
// empty. Off unless asked for (AnalyserParams::local_front_reach_cm); its foreground is used exactly as a
// learned background's (in_front_of(), foreground_candidates.hpp): candidates added beside the layers'.
//
// For a pixel (x, y) with a reading d > 0 and the reach R (mm), w = round(fx * R / d) pixels:
//   far(x, y) = min( max d(x-w .. x-1, y), max d(x+1 .. x+w, y) )       (readings of 0 count as 0)
// the nearer of the farthest readings within reach on either side: something in front of a wall has the
// wall on both sides, the wall itself (or the floor along a row) has itself. A side's range is clipped to
// the image; a side with no pixel or no reading, and a pixel without one, give far = 1 mm, in front of
// which nothing is.
// It is computed on a grid of kGridPx x kGridPx cells, each standing for its farthest reading (a cell's
// holes do not make it a hole), with d, the sides and w in cells, and every pixel of a cell gets its
// cell's far (the sides' maxima by a sparse table: a handful of operations a cell whatever the reach; w of
// each depth from a table made once per reach).
#include <opencv2/core.hpp>

#include "rdsf/frame/camera_model.hpp"

namespace rdsf {

constexpr int kLocalBackgroundGridPx = 4;

/// far(x, y) above for every pixel of `depth_mm` (the same size); throws Error when `reach_mm` is not
/// positive or the camera's fx is not.
cv::Mat1w local_background(const cv::Mat1w& depth_mm, const CameraModel& camera, double reach_mm);

/// The same into `far` (reallocated only when not of the frame's size, so a caller reusing it per thread
/// spares a frame's worth of fresh pages).
void local_background(const cv::Mat1w& depth_mm, const CameraModel& camera, double reach_mm, cv::Mat1w& far);

}  // namespace rdsf
