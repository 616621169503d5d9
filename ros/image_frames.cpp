#include "ros/image_frames.hpp"

#include <cmath>

#include <cv_bridge/cv_bridge.h>
#include <sensor_msgs/image_encodings.h>

#include "rdsf/core/error.hpp"
#include "rdsf/frame/depth_units.hpp"

namespace rdsf {
namespace {

namespace enc = sensor_msgs::image_encodings;

void check_size(const sensor_msgs::Image& image, int bytes_per_pixel, const std::string& topic) {
  if (image.width == 0 || image.height == 0) fail(topic, "empty image (" + image.encoding + ")");
  if (image.step < image.width * static_cast<std::uint32_t>(bytes_per_pixel) || image.step % bytes_per_pixel != 0 ||
      image.data.size() < static_cast<std::size_t>(image.step) * image.height) {
    fail(topic, image.encoding + " image of " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                    " with step " + std::to_string(image.step) + " and " + std::to_string(image.data.size()) +
                    " bytes: truncated");
  }
}

}  // namespace

CameraModel camera_model_of(const sensor_msgs::CameraInfo& info, int image_width, int image_height,
                            const std::string& topic) {
  if (!(info.K[0] > 0 && info.K[4] > 0) || !std::isfinite(info.K[0]) || !std::isfinite(info.K[4])) {
    fail(topic, "camera_info without a focal length (K[0] = " + std::to_string(info.K[0]) + ", K[4] = " +
                    std::to_string(info.K[4]) + "): the camera is not calibrated");
  }
  if (info.width == 0 || info.height == 0) fail(topic, "camera_info of size 0x0");
  CameraModel camera;
  camera.width_px = static_cast<int>(info.width);
  camera.height_px = static_cast<int>(info.height);
  camera.fx_px = info.K[0];
  camera.cx_px = info.K[2];
  camera.fy_px = info.K[4];
  camera.cy_px = info.K[5];
  if (camera.width_px == image_width && camera.height_px == image_height) return camera;
  return camera.scaled_to(image_width, image_height);
}

cv::Mat1w depth_mm_of(const sensor_msgs::Image& image, const std::string& topic) {
  if (image.is_bigendian) fail(topic, "big-endian depth image: not supported");
  if (image.encoding == enc::TYPE_16UC1 || image.encoding == enc::MONO16) {
    check_size(image, 2, topic);
    const cv::Mat1w view(static_cast<int>(image.height), static_cast<int>(image.width),
                         reinterpret_cast<std::uint16_t*>(const_cast<std::uint8_t*>(image.data.data())), image.step);
    return view.clone();
  }
  if (image.encoding == enc::TYPE_32FC1) {
    check_size(image, 4, topic);
    const cv::Mat1f metres(static_cast<int>(image.height), static_cast<int>(image.width),
                           reinterpret_cast<float*>(const_cast<std::uint8_t*>(image.data.data())), image.step);
    cv::Mat1w depth(metres.size());
    for (int y = 0; y < metres.rows; ++y) {
      const float* in = metres[y];
      std::uint16_t* out = depth[y];
      for (int x = 0; x < metres.cols; ++x) out[x] = depth_mm_of_metres(in[x]);
    }
    return depth;
  }
  fail(topic, "depth image in " + image.encoding + ": expected 16UC1 (millimetres) or 32FC1 (metres)");
}

cv::Mat3b bgr_of(const sensor_msgs::Image& image, const std::string& topic) {
  try {
    check_size(image, enc::numChannels(image.encoding) * enc::bitDepth(image.encoding) / 8, topic);
    const cv_bridge::CvImageConstPtr converted = cv_bridge::toCvShare(image, nullptr, enc::BGR8);
    return converted->image.clone();
  } catch (const cv_bridge::Exception& e) {
    fail(topic, std::string("colour image: ") + e.what());
  } catch (const cv::Exception& e) {
    fail(topic, "colour image in " + image.encoding + ": " + e.err);
  } catch (const Error&) {
    throw;
  } catch (const std::runtime_error& e) {  // image_encodings: an unknown encoding
    fail(topic, "colour image: " + std::string(e.what()));
  }
}

}  // namespace rdsf
