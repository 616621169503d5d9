#pragma once
// sensor_msgs/Image and CameraInfo as the library's frame pieces: depth in millimetres (uint16, 0 = no
// reading), registered colour as 8-bit BGR, and the pinhole camera model of the depth image. Each function
// throws rdsf::Error with one line naming the message's topic and the problem; the node counts such a
// message as refused and goes on.
#include <cstdint>
#include <string>

#include <opencv2/core.hpp>
#include <ros/time.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>

#include "rdsf/frame/camera_model.hpp"

namespace rdsf {

/// The camera model of `info` for an image of image_width x image_height pixels: fx = K[0], cx = K[2],
/// fy = K[4], cy = K[5] at info.width x info.height; an image of another size (binning, a resized stream)
/// gets the model scaled to it (CameraModel::scaled_to). Throws when fx or fy is not positive (an
/// uncalibrated camera sends K = 0) or the size is 0.
CameraModel camera_model_of(const sensor_msgs::CameraInfo& info, int image_width, int image_height,
                            const std::string& topic);

/// The depth image in millimetres: 16UC1 (and mono16) as it is; 32FC1 in metres rounded to the nearest
/// millimetre, where NaN, infinities, values <= 0 and beyond 65.535 m become 0 (no reading). A big-endian
/// image or another encoding is refused. The result owns its pixels.
cv::Mat1w depth_mm_of(const sensor_msgs::Image& image, const std::string& topic);

/// The colour image as 8-bit BGR (cv_bridge converts rgb8, bgra8, rgba8, mono8, ...). The result owns its
/// pixels.
cv::Mat3b bgr_of(const sensor_msgs::Image& image, const std::string& topic);

/// A ROS time in microseconds (the frames' timestamp_us).
inline std::int64_t time_us(const ros::Time& t) {
  return static_cast<std::int64_t>(t.sec) * 1000000 + static_cast<std::int64_t>(t.nsec) / 1000;
}

}  // namespace rdsf
