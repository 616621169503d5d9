#pragma once
// The floor of a recording, as rdsf-pcl-people gives it to PCL's ground-based people detector.
//
// The points of the recording's frames (every `stride_px`-th pixel with a reading, in metres, camera
// coordinates: x right, y down, z forward, x = (u - cx) z / fx, y = (v - cy) z / fy) are searched by RANSAC
// for planes within `max_tilt_deg` of horizontal (normal within that angle of the camera's y axis; a
// camera pitched or rolled by more than that finds no floor). Up to `max_planes` such planes with at least
// `min_inlier_share` of the points are taken out one after the other; the floor is the LOWEST of them
// (largest distance below the camera), so a table top or a seat is not taken for it.
// Result: coefficients (a, b, c, d) of a x + b y + c z + d = 0 with the normal pointing up (b < 0) and
// unit length, so d = the camera's height above the floor in metres.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "rdsf/frame/depth_frame.hpp"

namespace rdsf::peers {

struct GroundParams {
  int stride_px = 4;               ///< every this-many-th row and column
  double max_tilt_deg = 25;        ///< planes whose normal is within this of the y axis
  double inlier_distance_m = 0.04; ///< RANSAC's distance threshold (the 8-bit frames' steps are ~2 cm)
  int max_planes = 3;
  double min_inlier_share = 0.03;  ///< of the sampled points
  double max_range_m = 6;          ///< points beyond are not sampled (noise grows with distance squared)
};

/// Fits the floor to the frames of one recording; nullopt when no horizontal plane qualifies.
std::optional<Eigen::Vector4f> fit_ground(const std::vector<const DepthFrame*>& frames, const GroundParams& params);

}  // namespace rdsf::peers
