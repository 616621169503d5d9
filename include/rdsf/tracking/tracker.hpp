#pragma once
// Tracking as the thesis describes it. Each tracked person keeps a colour histogram of their masked colour
// crop, the present and previous centroid (box centre at the layer depth, in centimetres through the camera
// model), the distance covered and a box colour. For a detection and a person,
//     lkh = bhattacharyya_distance(histograms) + (d_cm / 98 - 1 / 49)
// where d_cm is the distance between the detection's centroid and the person's present centroid (the
// distance term is 0 at 2 cm and 1 at 100 cm). A pair matches when lkh <= threshold_lkh; pairs are taken
// smallest lkh first, each person and each detection at most once; an unmatched detection creates a person.
// Without colour the histogram term is dropped (lkh is the distance term alone), so the same threshold
// means "within threshold_lkh * 98 + 2 cm".
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/core/parameter_table.hpp"
#include "rdsf/frame/camera_model.hpp"
#include "rdsf/tracking/colour_histogram.hpp"

namespace rdsf {

struct TrackingParams {
  /// A detection matches a person when lkh <= threshold_lkh.
  double threshold_lkh = 0.6;
  /// A person not matched for this many frames is no longer matched (0: never forgotten).
  int max_missed_frames = 15;
  /// Bins per colour channel of the histograms.
  int histogram_bins = 8;
};

/// The tracker's options (--threshold-lkh, --max-missed-frames, --histogram-bins), declared once
/// (core/parameter_table.hpp): name, help and check of each member of TrackingParams.
const ParameterTable<TrackingParams>& tracking_parameters();

/// What the tracker needs of a detection.
struct TrackInput {
  cv::Rect box;                ///< strict box, pixels
  double depth_mm = 0;         ///< layer depth
  ColourHistogram histogram;   ///< empty without colour
};

struct TrackedPerson {
  int id = 0;                  ///< 1, 2, ... in order of creation
  ColourHistogram histogram;   ///< of the last matched detection
  cv::Point3d centroid_cm;     ///< present centroid
  cv::Point3d previous_cm;     ///< centroid before the last match
  double distance_cm = 0;      ///< distance covered so far
  cv::Scalar colour;           ///< box colour (BGR), random but fixed per id
  std::int64_t last_frame = 0; ///< frame index of the last match
  cv::Rect box;                ///< last box
};

/// The centroid of a box at a depth, in centimetres in the camera frame.
cv::Point3d centroid_cm(const cv::Rect& box, double depth_mm, const CameraModel& camera);

/// The thesis's match score (histogram term dropped when either histogram is empty).
double match_lkh(const ColourHistogram& a, const ColourHistogram& b, double distance_cm);

class Tracker {
 public:
  explicit Tracker(TrackingParams params = {}, std::uint64_t colour_seed = 1);

  /// Matches the detections of frame `frame_index` and returns the person id of each.
  std::vector<int> update(const std::vector<TrackInput>& detections, const CameraModel& camera,
                          std::int64_t frame_index);

  const std::vector<TrackedPerson>& people() const { return people_; }
  const TrackedPerson* person(int id) const;

 private:
  TrackingParams params_;
  std::uint64_t colour_state_;
  std::vector<TrackedPerson> people_;
};

}  // namespace rdsf
