#pragma once
// The payloads of sensor_msgs/CompressedImage as ROS 1 robots record them (image_transport's "compressed"
// transport for colour, "compressedDepth" for depth: what `rosbag record .../image_raw/compressedDepth`
// keeps), decoded without ROS: the bag source reads them (frame/bag_source.hpp), and so does a fuzz target.
//
// format (the message's `format` field):
//   "ENC; compressedDepth png", "ENC; compressedDepth rvl", or "ENC; compressedDepth" (png: the transport's
//     format before RVL existed): depth, ENC = 16UC1 or mono16 (depth units) or 32FC1 (metres);
//   anything else naming jpeg or png ("rgb8; jpeg compressed bgr8", "bgr8; png compressed bgr8", "jpeg"):
//     colour; the word after "compressed" is the channel order of the encoded image (bgr8 unless rgb8).
// compressedDepth data: a 12-byte header (int32 kind, float32 A, float32 B; little-endian), then the 16-bit
//   samples q of the image as a PNG (16-bit grey) or as RVL (uint32 columns, uint32 rows, then the stream):
//   ENC 16UC1 / mono16: q is the depth in units; depth_mm = round(q * unit_mm), > 65535 -> 0 (no reading);
//   ENC 32FC1: inverse depth quantised by the recorder: q = 0 is no reading, else
//     depth_m = A / (q - B) in float32, depth_mm = round(1000 * depth_m), and non-finite, <= 0 or > 65535 mm
//     -> 0 (a 32FC1 image's rule). The recorder's quantisation (A = Z0 (Z0 + 1), B = 1 - A / max_depth,
//     q = trunc(A / d + B)) makes the step d^2 / A: 1.6 mm at 4 m for its default Z0 = 100.
// RVL (A. D. Wilson, "Fast lossless depth image compression", 2017): a stream of 32-bit little-endian words,
//   each holding eight 4-bit groups read from its most significant end; a value is one or more groups, each
//   giving the value's next 3 bits (least significant first) and, in its high bit, whether another follows.
//   The values, until every pixel is written in row order: a count of zero pixels, a count of non-zero
//   pixels, and for each non-zero pixel its difference from the previous non-zero pixel (0 before the
//   first), zigzag-coded (2d for d >= 0, -2d - 1 for d < 0), the sum taken modulo 2^16.
// Every fault (an unknown format or encoding, a short header, a damaged PNG, an RVL stream that ends early
// or writes past the image, an image over 16384 x 16384 or 2^26 pixels) throws Error "WHERE: problem".
#include <cstddef>
#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

namespace rdsf {

/// True when `format` is a compressedDepth format (above).
bool is_compressed_depth_format(const std::string& format);

/// The image encoding `format` names before its ';' ("16UC1" of "16UC1; compressedDepth png"), or empty.
std::string compressed_image_encoding(const std::string& format);

/// Depth in millimetres from compressedDepth `data[0..size)` of `format` (rules above); `unit_mm` scales
/// 16UC1 / mono16 units. `where` names the message in errors.
cv::Mat1w decode_compressed_depth(const std::string& where, const std::string& format, const std::uint8_t* data,
                                  std::size_t size, double unit_mm = 1.0);

/// A colour image (BGR) from compressed `data[0..size)` of `format` (jpeg or png; a grey one becomes three
/// equal channels). `where` names the message in errors.
cv::Mat3b decode_compressed_colour(const std::string& where, const std::string& format, const std::uint8_t* data,
                                   std::size_t size);

}  // namespace rdsf
