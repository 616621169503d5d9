#include "rdsf/frame/depth_png.hpp"

#include <vector>

#include <opencv2/imgproc.hpp>

#include "rdsf/core/durable_io.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/frame/image_codecs.hpp"
#include "rdsf/frame/png_decoder.hpp"

namespace rdsf {

cv::Mat1w read_depth_png(const std::string& path) {
  const cv::Mat image = read_png_file(path);
  if (image.channels() != 1) {
    fail(path, std::to_string(image.channels()) +
                   "-channel image given as depth (expected 16-bit single-channel PNG in millimetres)");
  }
  if (image.depth() != CV_16U) {
    fail(path, "8-bit image given as depth (expected 16-bit single-channel PNG in millimetres)");
  }
  return image;
}

cv::Mat3b read_colour_png(const std::string& path, cv::Size expected) {
  const cv::Mat image = read_png_file(path);
  if (image.depth() != CV_8U) fail(path, "colour image must be 8-bit");
  cv::Mat3b bgr;
  switch (image.channels()) {
    case 1: cv::cvtColor(image, bgr, cv::COLOR_GRAY2BGR); break;
    case 3: bgr = image; break;
    case 4: cv::cvtColor(image, bgr, cv::COLOR_BGRA2BGR); break;
    default: fail(path, "colour image has " + std::to_string(image.channels()) + " channels");
  }
  if (expected.area() > 0 && bgr.size() != expected) {
    fail(path, "colour image is " + std::to_string(bgr.cols) + "x" + std::to_string(bgr.rows) +
                   " but its depth image is " + std::to_string(expected.width) + "x" +
                   std::to_string(expected.height));
  }
  return bgr;
}

void write_png_atomically(const std::string& path, const cv::Mat& image) {
  std::vector<unsigned char> bytes;
  if (!opencv_encode_png(image, bytes, kOpenCvDefaultPngParams)) fail(path, "cannot encode image as PNG");
  write_file_durably(path, bytes);
}

}  // namespace rdsf
