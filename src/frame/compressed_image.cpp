#include "rdsf/frame/compressed_image.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "rdsf/core/byte_order.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/frame/depth_units.hpp"
#include "rdsf/frame/image_codecs.hpp"
#include "rdsf/frame/png_decoder.hpp"

namespace rdsf {
namespace {

constexpr std::size_t kHeaderBytes = 12;  // int32 kind, float32 A, float32 B
constexpr std::uint32_t kMaxSidePx = 16384;
constexpr std::uint64_t kMaxPixels = std::uint64_t{1} << 26;

float little_endian_f32(const std::uint8_t* p) {
  const std::uint32_t bits = load_little_endian_u32(p);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// The values of an RVL stream (the header's rule), one at a time.
class RvlValues {
 public:
  RvlValues(const std::string& where, const std::uint8_t* data, std::size_t size)
      : where_(where), data_(data), size_(size) {}

  std::uint64_t next() {
    std::uint64_t value = 0;
    for (int shift = 0;; shift += 3) {
      if (shift > 30) fail(where_, "RVL value longer than 33 bits (a damaged stream)");
      if (groups_left_ == 0) {
        if (size_ - position_ < 4) fail(where_, "RVL stream ends before the image is complete");
        word_ = load_little_endian_u32(data_ + position_);
        position_ += 4;
        groups_left_ = 8;
      }
      const std::uint32_t group = word_ >> 28;
      word_ <<= 4;
      --groups_left_;
      value |= static_cast<std::uint64_t>(group & 7u) << shift;
      if ((group & 8u) == 0) return value;
    }
  }

 private:
  const std::string& where_;
  const std::uint8_t* data_;
  std::size_t size_, position_ = 0;
  std::uint32_t word_ = 0;
  int groups_left_ = 0;
};

// The 16-bit samples of an RVL image: uint32 columns, uint32 rows, the stream.
cv::Mat1w decode_rvl(const std::string& where, const std::uint8_t* data, std::size_t size) {
  if (size < 8) fail(where, "RVL image without its size (" + std::to_string(size) + " bytes)");
  const std::uint32_t cols = load_little_endian_u32(data), rows = load_little_endian_u32(data + 4);
  if (cols == 0 || rows == 0 || cols > kMaxSidePx || rows > kMaxSidePx ||
      static_cast<std::uint64_t>(cols) * rows > kMaxPixels) {
    fail(where, "RVL image of " + std::to_string(cols) + "x" + std::to_string(rows) + " pixels: not a depth image");
  }
  cv::Mat1w samples(static_cast<int>(rows), static_cast<int>(cols));
  std::uint16_t* out = samples[0];  // continuous: made here
  const std::uint64_t pixels = static_cast<std::uint64_t>(cols) * rows;
  RvlValues values(where, data + 8, size - 8);
  std::uint64_t written = 0;
  std::uint16_t previous = 0;
  const auto check_run = [&](std::uint64_t run) {
    if (run > pixels - written) fail(where, "RVL stream writes past the image's " + std::to_string(pixels) + " pixels");
  };
  while (written < pixels) {
    const std::uint64_t zeros = values.next();
    check_run(zeros);
    std::memset(out + written, 0, zeros * sizeof(std::uint16_t));
    written += zeros;
    if (written == pixels) break;  // the count of non-zero pixels after the last zeros may be left out
    const std::uint64_t nonzeros = values.next();
    check_run(nonzeros);
    for (std::uint64_t i = 0; i < nonzeros; ++i) {
      const std::uint64_t zigzag = values.next();
      const std::uint64_t difference = (zigzag >> 1) ^ (~(zigzag & 1) + 1);  // -(zigzag & 1): all ones when odd
      previous = static_cast<std::uint16_t>(previous + difference);         // modulo 2^16
      out[written++] = previous;
    }
  }
  return samples;
}

}  // namespace

bool is_compressed_depth_format(const std::string& format) {
  return format.find("compressedDepth") != std::string::npos;
}

std::string compressed_image_encoding(const std::string& format) {
  const auto semicolon = format.find(';');
  if (semicolon == std::string::npos) return {};
  std::string encoding = format.substr(0, semicolon);
  while (!encoding.empty() && encoding.back() == ' ') encoding.pop_back();
  return encoding;
}

cv::Mat1w decode_compressed_depth(const std::string& where, const std::string& format, const std::uint8_t* data,
                                  std::size_t size, double unit_mm) {
  if (!is_compressed_depth_format(format)) fail(where, "format '" + format + "' is not compressedDepth");
  const std::string encoding = compressed_image_encoding(format);
  const bool metres = encoding == "32FC1";
  if (!metres && encoding != "16UC1" && encoding != "mono16") {
    fail(where, "compressedDepth of encoding '" + encoding + "' (16UC1, mono16 or 32FC1 are depth)");
  }
  const std::string compression = format.substr(format.find("compressedDepth") + 15);
  const bool rvl = compression.find("rvl") != std::string::npos;
  if (!rvl && compression.find_first_not_of(' ') != std::string::npos && compression.find("png") == std::string::npos) {
    fail(where, "compressedDepth compression '" + compression + "' (png or rvl are read)");
  }
  if (size < kHeaderBytes) fail(where, "compressedDepth of " + std::to_string(size) + " bytes has no header");
  const std::uint32_t kind = load_little_endian_u32(data);
  const float a = little_endian_f32(data + 4), b = little_endian_f32(data + 8);
  const std::uint8_t* image = data + kHeaderBytes;
  const std::size_t image_bytes = size - kHeaderBytes;
  cv::Mat1w samples;
  if (rvl) {
    samples = decode_rvl(where, image, image_bytes);
  } else {
    // The PNG's own size (IHDR, big-endian after the 8-byte signature and the chunk's length and type) is
    // checked before anything of that size is made.
    if (image_bytes >= 24) {
      const std::uint32_t cols = load_big_endian_u32(image + 16), rows = load_big_endian_u32(image + 20);
      if (cols > kMaxSidePx || rows > kMaxSidePx || static_cast<std::uint64_t>(cols) * rows > kMaxPixels) {
        fail(where, "compressedDepth PNG of " + std::to_string(cols) + "x" + std::to_string(rows) +
                        " pixels: not a depth image");
      }
    }
    const cv::Mat png = decode_png(where, image, image_bytes);
    if (png.type() != CV_16UC1) fail(where, "compressedDepth PNG is not 16-bit grey");
    samples = png;
  }
  if (metres) {
    if (kind != 0 || !std::isfinite(a) || !std::isfinite(b)) {
      fail(where, "32FC1 compressedDepth header (kind " + std::to_string(kind) + ", A " + std::to_string(a) + ", B " +
                      std::to_string(b) + ") is not an inverse-depth quantisation");
    }
    for (int y = 0; y < samples.rows; ++y) {
      std::uint16_t* row = samples[y];
      for (int x = 0; x < samples.cols; ++x) {
        row[x] = row[x] == 0 ? 0 : depth_mm_of_metres(a / (static_cast<float>(row[x]) - b));
      }
    }
  } else if (unit_mm != 1.0) {
    for (int y = 0; y < samples.rows; ++y) {
      std::uint16_t* row = samples[y];
      for (int x = 0; x < samples.cols; ++x) row[x] = depth_mm_of_units(row[x], unit_mm);
    }
  }
  return samples;
}

cv::Mat3b decode_compressed_colour(const std::string& where, const std::string& format, const std::uint8_t* data,
                                   std::size_t size) {
  if (is_compressed_depth_format(format)) fail(where, "format '" + format + "' is depth, not colour");
  if (format.find("jpeg") == std::string::npos && format.find("png") == std::string::npos) {
    fail(where, "compressed colour format '" + format + "' (jpeg or png are read)");
  }
  if (size == 0 || size > static_cast<std::size_t>(INT32_MAX)) {
    fail(where, "compressed colour image of " + std::to_string(size) + " bytes");
  }
  cv::Mat decoded;
  try {
    decoded = opencv_decode_image(data, size, DecodedAs::colour);
  } catch (const cv::Exception& e) {
    fail(where, "compressed colour image cannot be decoded (" + e.err + ")");
  }
  if (decoded.empty() || decoded.type() != CV_8UC3) fail(where, "compressed colour image cannot be decoded");
  const auto after = format.find("compressed ");
  if (after != std::string::npos && format.compare(after + 11, 4, "rgb8") == 0) {
    cv::cvtColor(decoded, decoded, cv::COLOR_RGB2BGR);  // the encoded image's channels were red first
  }
  return decoded;
}

}  // namespace rdsf
