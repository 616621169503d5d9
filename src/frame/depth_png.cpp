#include "frame/depth_png.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace rdsf {
namespace {

const unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

// Reads the whole file and decodes it, so that a missing, non-PNG or corrupt file is told apart.
cv::Mat decode_png(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail(path, "no such file");
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a folder, expected a PNG file");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be opened for reading");
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 8 || !std::equal(kPngSignature, kPngSignature + 8, bytes.begin())) {
    fail(path, "not a PNG file");
  }
  // A PNG ends with an IEND chunk; without it the file was cut short (libpng would decode garbage rows).
  static const unsigned char kIend[8] = {'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
  if (bytes.size() < 20 || !std::equal(kIend, kIend + 8, bytes.end() - 8)) {
    fail(path, "truncated or corrupt PNG (no IEND chunk at the end)");
  }
  cv::Mat image;
  try {
    image = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception&) {
    image.release();
  }
  if (image.empty()) fail(path, "corrupt PNG (cannot be decoded)");
  return image;
}

}  // namespace

cv::Mat1w read_depth_png(const std::string& path) {
  const cv::Mat image = decode_png(path);
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
  const cv::Mat image = decode_png(path);
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
  if (!cv::imencode(".png", image, bytes)) fail(path, "cannot encode image as PNG");
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) fail(temporary, "cannot be opened for writing");
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) fail(temporary, "write failed (disk full?)");
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) fail(path, "cannot rename temporary file into place: " + ec.message());
}

}  // namespace rdsf
