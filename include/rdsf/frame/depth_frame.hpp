#pragma once
// One frame of a depth camera, with its units stated: depth in millimetres as uint16 (0 = no reading),
// an optional 8-bit BGR colour image registered to the depth (same size, pixel for pixel), where it came
// from and when, and the camera model that produced it.
#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

#include "rdsf/frame/camera_model.hpp"

namespace rdsf {

/// The time between frames of a source without a clock (image folders): the Kinect's 30 frames per second,
/// in whole microseconds. Frame i of such a source has timestamp_us = i * kFrameIntervalUs.
inline constexpr std::int64_t kFrameIntervalUs = 33333;

struct DepthFrame {
  cv::Mat1w depth_mm;             ///< CV_16UC1, millimetres, 0 = no reading
  cv::Mat3b bgr;                  ///< CV_8UC3 registered colour, empty when the source has none
  std::int64_t index = 0;         ///< 0-based position of the frame in its source
  std::string name;               ///< file stem (without .depth.png) for folders, the index for recordings
  std::int64_t timestamp_us = 0;  ///< microseconds; from the recording, or index * kFrameIntervalUs for image folders
  CameraModel camera;             ///< intrinsics of the depth image as delivered
  /// |colour stamp - depth stamp| in microseconds when the source paired separately stamped streams (bags);
  /// 0 when colour comes registered with the depth (folders, OpenNI2) or there is none.
  std::int64_t colour_gap_us = 0;

  bool has_colour() const { return !bgr.empty(); }
  int width_px() const { return depth_mm.cols; }
  int height_px() const { return depth_mm.rows; }
};

}  // namespace rdsf
