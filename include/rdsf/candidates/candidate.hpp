#pragma once
// A person candidate: an upright object found in one depth layer, with its boxes and its 64x128 crops.
#include <opencv2/core.hpp>

namespace rdsf {

struct Candidate {
  /// The "strict box": height from the highest to the lowest point of the object, width = height / 2,
  /// centred on the column of the highest point; clipped to the image. Pixels.
  cv::Rect strict_box;
  /// The "fitted box": the real extent of the object's pixels, left to right over the columns that pass
  /// threshold_height, top to bottom from the highest to the lowest point (the strict box's rows); inside
  /// the image. What detections report by default (BoxKind::fitted); the strict box and window stay what
  /// the crop is cut from.
  cv::Rect fitted_box;
  /// The strict box enlarged by window_scale about its centre, before clipping (may leave the image).
  cv::Rect window_unclipped;
  /// window_unclipped clipped to the image: what is cut out.
  cv::Rect window;
  int layer = 0;              ///< label of the depth layer (Segmentation::labels)
  double layer_depth_mm = 0;  ///< mean depth of that layer
  double height_cm = 0;       ///< real height of the object (tallest column run)
  double width_cm = 0;        ///< real width of the object (its passing columns)
  int highest_column = 0;     ///< image column of the highest point
  bool part = false;          ///< a piece split off a wider object (CandidateParams::split_*)
  /// The object it is, or was cut from: unique in the frame, shared by a whole object and its pieces
  /// (duplicate_candidates.hpp), in find_candidates()'s order of layers and objects.
  int object = 0;
  /// The window's depth, only the layer's pixels (others 0), resized to the crop size by nearest
  /// neighbour (no blending of masked zeros into depths); the image outside the frame reads 0. CV_16UC1.
  cv::Mat1w depth_crop;
  /// The window's colour, only the layer's pixels (others black), same sampling; empty without colour.
  cv::Mat3b colour_crop;
};

/// Which of a candidate's boxes detections, CSVs and the evaluation report.
enum class BoxKind {
  fitted,  ///< Candidate::fitted_box (default)
  strict,  ///< Candidate::strict_box (the thesis)
};

inline const cv::Rect& reported_box(const Candidate& candidate, BoxKind kind) {
  return kind == BoxKind::strict ? candidate.strict_box : candidate.fitted_box;
}

}  // namespace rdsf
