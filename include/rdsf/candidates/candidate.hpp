#pragma once
// A person candidate: an upright object found in one depth layer, with its boxes and its 64x128 crops.
#include <opencv2/core.hpp>

namespace rdsf {

struct Candidate {
  /// The "strict box": height from the highest to the lowest point of the object, width = height / 2 in
  /// metres (lround(height_px * fx / fy / 2) columns: height_px / 2 for square pixels), centred on the
  /// column of the highest point; clipped to the image. Pixels.
  cv::Rect strict_box;
  /// The object's extent: left to right over the columns that pass threshold_height and the pieces
  /// attached to them (CandidateParams::fit_*), top to bottom from the highest to the lowest point (the
  /// strict box's rows); inside the image. Labelling by overlap with true boxes uses it (labelling_box()):
  /// a candidate is a positive when the layer's pixels, which its crop shows, are mostly the person.
  cv::Rect extent_box;
  /// The "fitted box": extent_box widened about its centre to CandidateParams::fit.min_width_ratio of its
  /// height (in metres, as the strict box) when narrower (a person's limbs swung out of the layer), clipped to the image. What detections
  /// report by default (BoxKind::fitted); the strict box and window stay what the crop is cut from.
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
  /// Found among the pixels in front of a background model of the room (foreground_candidates.hpp): its
  /// crops hold only those pixels of its layer (FrameAnalysis::in_front's labels, not the layer's).
  bool foreground = false;
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

/// The box a candidate is labelled by (its overlap with true boxes): the strict box with BoxKind::strict,
/// else its extent (Candidate::extent_box), not the fitted box's widening, so that what labels the
/// training crops does not change with fit.min_width_ratio (docs/candidates.md).
inline const cv::Rect& labelling_box(const Candidate& candidate, BoxKind kind) {
  return kind == BoxKind::strict ? candidate.strict_box : candidate.extent_box;
}

}  // namespace rdsf
