#pragma once
// An object's height at its own depth, in cm (CandidateParams::max_height_cm). The layer's mean depth
// (Candidate::layer_depth_mm) can be metres off an object's own: a layer spans up to candidate_threshold of
// depth, and on the 16 held-out synthetic rooms 18 of 608 people came out 2.2-3.0 m tall by it
// (docs/quality.md, "Metric size as features"). The object's depth here is the median of its depth crop's
// readings, which hold only its layer's pixels within its window:
//   height_cm = strict_box.height (px) x object_depth_mm / fy_px / 10.
// The strict box is clipped to the image, so for an object cut by the image's top or bottom this is the
// height of what the image shows (a lower bound of the object's).
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/candidates/candidate.hpp"
#include "rdsf/frame/camera_model.hpp"

namespace rdsf {

/// The median of the crop's readings (the (n/2)-th smallest, 0-based, of its n non-zero values), in mm;
/// 0 when it has none.
double object_depth_mm(const cv::Mat1w& depth_crop);

/// The candidate's strict box height in cm at object_depth_mm() of its depth crop; 0 without readings.
double object_height_cm(const Candidate& candidate, const CameraModel& camera);

/// Whether a candidate is taller than `max_height_cm` at its own depth (no person is): false when
/// max_height_cm is 0 (off) or the crop has no readings. The same as object_height_cm() > max_height_cm,
/// but the median is only taken when the crop's farthest reading makes the object too tall.
bool taller_than_a_person(const Candidate& candidate, const CameraModel& camera, double max_height_cm);

}  // namespace rdsf
