#include "rdsf/frame/depth_png.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "rdsf/core/durable_io.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/yaml_guard.hpp"

namespace rdsf {
namespace {

const unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

std::uint32_t crc32(const unsigned char* data, std::size_t size) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1U) ? 0xedb88320U ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xffffffffU;
  for (std::size_t i = 0; i < size; ++i) c = table[(c ^ data[i]) & 0xffU] ^ (c >> 8);
  return c ^ 0xffffffffU;
}

std::uint32_t big_endian(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}

// Walks the PNG chunks and checks every CRC, so that a truncated or damaged file is reported here in one
// line, before libpng would print its own messages.
void check_png_structure(const std::string& path, const std::vector<unsigned char>& bytes) {
  if (bytes.size() < 8 || !std::equal(kPngSignature, kPngSignature + 8, bytes.begin())) {
    fail(path, "not a PNG file");
  }
  std::size_t at = 8;
  while (true) {
    if (at + 12 > bytes.size()) {
      fail(path, "truncated PNG (file ends at byte " + std::to_string(bytes.size()) + " before the IEND chunk)");
    }
    const std::size_t length = big_endian(&bytes[at]);
    if (length > bytes.size() - at - 12) {
      fail(path, "truncated PNG (chunk at byte " + std::to_string(at) + " runs past the end of the file)");
    }
    const std::string type(reinterpret_cast<const char*>(&bytes[at + 4]), 4);
    if (crc32(&bytes[at + 4], length + 4) != big_endian(&bytes[at + 8 + length])) {
      fail(path, "corrupt PNG (CRC error in " + one_line(type) + " chunk at byte " + std::to_string(at) + ")");
    }
    at += length + 12;
    if (type == "IEND") return;
  }
}

// Reads the whole file and decodes it, so that a missing, non-PNG or corrupt file is told apart.
cv::Mat decode_png(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail(path, "no such file");
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a folder, expected a PNG file");
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) fail(path, "cannot be opened for reading");
  const std::streamsize size = in.tellg();
  in.seekg(0);
  std::vector<unsigned char> bytes(static_cast<std::size_t>(std::max<std::streamsize>(0, size)));
  if (size > 0 && !in.read(reinterpret_cast<char*>(bytes.data()), size)) fail(path, "cannot be read");
  check_png_structure(path, bytes);
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
  write_file_durably(path, bytes);
}

}  // namespace rdsf
