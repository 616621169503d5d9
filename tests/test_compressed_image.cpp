// sensor_msgs/CompressedImage payloads decoded without ROS (rdsf/frame/compressed_image.hpp): compressedDepth
// as PNG and RVL, 16UC1 and 32FC1, compressed colour (png, jpeg; channel order), and the faults as one-line
// errors naming the message. Bags of such topics: test_bag_compressed.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "rdsf/frame/compressed_image.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

// The 12-byte compressedDepth header (kind 0, A, B) followed by `body`.
std::vector<std::uint8_t> with_header(const std::vector<std::uint8_t>& body, float a = 0, float b = 0) {
  std::vector<std::uint8_t> out(12 + body.size(), 0);
  std::memcpy(out.data() + 4, &a, 4);  // this machine is little-endian, as the format
  std::memcpy(out.data() + 8, &b, 4);
  std::copy(body.begin(), body.end(), out.begin() + 12);
  return out;
}

std::vector<std::uint8_t> png_of(const cv::Mat& image) {
  std::vector<std::uint8_t> bytes;
  EXPECT_TRUE(cv::imencode(".png", image, bytes));
  return bytes;
}

std::vector<std::uint8_t> little_endian_words(const std::vector<std::uint32_t>& words) {
  std::vector<std::uint8_t> out;
  for (std::uint32_t w : words) {
    for (int k = 0; k < 4; ++k) out.push_back(static_cast<std::uint8_t>(w >> (8 * k)));
  }
  return out;
}

cv::Mat1w decode_depth(const std::vector<std::uint8_t>& data, const std::string& format, double unit_mm = 1.0) {
  return decode_compressed_depth("msg", format, data.data(), data.size(), unit_mm);
}

}  // namespace

TEST(CompressedImage, FormatsAreToldApart) {
  EXPECT_TRUE(is_compressed_depth_format("16UC1; compressedDepth png"));
  EXPECT_TRUE(is_compressed_depth_format("32FC1; compressedDepth"));
  EXPECT_FALSE(is_compressed_depth_format("rgb8; jpeg compressed bgr8"));
  EXPECT_EQ(compressed_image_encoding("16UC1; compressedDepth rvl"), "16UC1");
  EXPECT_EQ(compressed_image_encoding("rgb8; jpeg compressed bgr8"), "rgb8");
  EXPECT_EQ(compressed_image_encoding("jpeg"), "");
}

// RVL worked by hand: pixels 0 0 5 5 0 in one row. The values: 2 zeros, 2 non-zeros, +5 (zigzag 10 = groups
// 2 then 1, the first with its "more" bit: 0xA, 0x1), +0 (0), 1 zero, 0 non-zeros: groups 2 2 A 1 0 1 0, then
// one empty group to fill the word: 0x22A10100.
TEST(CompressedImage, RvlWorkedByHandDecodes) {
  std::vector<std::uint8_t> rvl = little_endian_words({5, 1, 0x22A10100u});
  const cv::Mat1w depth = decode_depth(with_header(rvl), "16UC1; compressedDepth rvl");
  ASSERT_EQ(depth.size(), cv::Size(5, 1));
  EXPECT_EQ(std::vector<std::uint16_t>(depth.begin(), depth.end()), (std::vector<std::uint16_t>{0, 0, 5, 5, 0}));

  // A difference below the previous value (5 then 3: -2, zigzag 3) and one wrapping modulo 2^16 (3 + 65535 =
  // 2). Values: 0 zeros, 3 non-zeros, +5 (A 1), -2 (3), +65535 (zigzag 131070: 3-bit groups 6 7 7 7 7 3, each
  // but the last with its "more" bit: E F F F F 3): groups 0 3 A 1 3 E F F | F F 3, the image then complete.
  rvl = little_endian_words({3, 1, 0x03A13EFFu, 0xFF300000u});
  const cv::Mat1w wrapped = decode_depth(with_header(rvl), "16UC1; compressedDepth rvl");
  EXPECT_EQ(std::vector<std::uint16_t>(wrapped.begin(), wrapped.end()), (std::vector<std::uint16_t>{5, 3, 2}));
}

TEST(CompressedImage, SixteenBitPngIsTheDepthAndUnitsScaleIt) {
  cv::Mat1w depth(48, 64);
  cv::randu(depth, 0, 9000);
  depth(0, 0) = 0;
  const std::vector<std::uint8_t> data = with_header(png_of(depth));
  const cv::Mat1w read = decode_depth(data, "16UC1; compressedDepth png");
  EXPECT_EQ(cv::norm(read, depth, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(decode_depth(data, "16UC1; compressedDepth"), depth, cv::NORM_INF), 0);  // png, the old format
  const cv::Mat1w tenths = decode_depth(data, "mono16; compressedDepth png", 0.1);  // 0.1 mm units
  EXPECT_EQ(tenths(0, 0), 0);
  EXPECT_EQ(tenths(5, 7), static_cast<std::uint16_t>(std::nearbyint(depth(5, 7) * 0.1)));
}

// 32FC1: the recorder's inverse depth q = trunc(A / d + B), A = 100 x 101, B = 1 - A / 10 m; decoded to
// within the quantisation step d^2 / A (plus the millimetre's rounding), 0 staying no reading.
TEST(CompressedImage, FloatDepthIsTheInverseOfTheRecordersQuantisation) {
  const float a = 100.0f * 101.0f, b = 1.0f - a / 10.0f;
  cv::Mat1w truth(1, 9000), q(1, 9000);
  for (int i = 0; i < truth.cols; ++i) {
    truth(0, i) = static_cast<std::uint16_t>(i == 0 ? 0 : 400 + i);  // 0.4-9.4 m
    const float metres = truth(0, i) / 1000.0f;
    q(0, i) = i == 0 ? 0 : static_cast<std::uint16_t>(a / metres + b);
  }
  const cv::Mat1w read = decode_depth(with_header(png_of(q), a, b), "32FC1; compressedDepth png");
  EXPECT_EQ(read(0, 0), 0);
  for (int i = 1; i < truth.cols; ++i) {
    const double d_m = truth(0, i) / 1000.0;
    ASSERT_NEAR(read(0, i), truth(0, i), 1000.0 * d_m * d_m / a + 1.0) << truth(0, i) << " mm";
  }
  // A header that is no quantisation (NaN A) is refused for 32FC1.
  const std::string e = test::error_message(
      [&] { decode_depth(with_header(png_of(q), std::nanf(""), b), "32FC1; compressedDepth png"); });
  EXPECT_EQ(e.rfind("msg: 32FC1 compressedDepth header", 0), 0u) << e;
}

TEST(CompressedImage, ColourInEitherChannelOrderAndJpeg) {
  cv::Mat3b bgr(40, 60);
  cv::randu(bgr, 0, 255);
  const std::vector<std::uint8_t> png = png_of(bgr);
  cv::Mat3b read = decode_compressed_colour("msg", "rgb8; png compressed bgr8", png.data(), png.size());
  EXPECT_EQ(cv::norm(read, bgr, cv::NORM_INF), 0);
  // The encoded image's channels were red first: swapped back.
  read = decode_compressed_colour("msg", "rgb8; png compressed rgb8", png.data(), png.size());
  cv::Mat3b swapped;
  cv::cvtColor(bgr, swapped, cv::COLOR_BGR2RGB);
  EXPECT_EQ(cv::norm(read, swapped, cv::NORM_INF), 0);
  // JPEG of a smooth image: close to it.
  cv::Mat3b smooth(40, 60);
  for (int y = 0; y < smooth.rows; ++y)
    for (int x = 0; x < smooth.cols; ++x) smooth(y, x) = cv::Vec3b(static_cast<uchar>(4 * x), static_cast<uchar>(5 * y), 128);
  std::vector<std::uint8_t> jpeg;
  ASSERT_TRUE(cv::imencode(".jpg", smooth, jpeg, {cv::IMWRITE_JPEG_QUALITY, 95}));
  read = decode_compressed_colour("msg", "bgr8; jpeg compressed bgr8", jpeg.data(), jpeg.size());
  EXPECT_LT(cv::norm(read, smooth, cv::NORM_L1) / smooth.total() / 3, 3.0);
}

TEST(CompressedImage, FaultsAreOneLineErrorsNamingTheMessage) {
  const auto depth_error = [](const std::vector<std::uint8_t>& data, const std::string& format) {
    return test::error_message([&] { decode_depth(data, format); });
  };
  const std::vector<std::uint8_t> hand = little_endian_words({5, 1, 0x22A10100u});
  std::string e = depth_error(with_header({hand.begin(), hand.begin() + 8}), "16UC1; compressedDepth rvl");
  EXPECT_EQ(e, "msg: RVL stream ends before the image is complete");
  e = depth_error(with_header(little_endian_words({3, 1, 0x22A10100u})), "16UC1; compressedDepth rvl");  // 3 pixels
  EXPECT_EQ(e, "msg: RVL stream writes past the image's 3 pixels");
  e = depth_error(with_header(little_endian_words({0, 1, 0})), "16UC1; compressedDepth rvl");
  EXPECT_EQ(e, "msg: RVL image of 0x1 pixels: not a depth image");
  e = depth_error(with_header(little_endian_words({1, 1, 0xFFFFFFFFu, 0xFFFFFFFFu})), "16UC1; compressedDepth rvl");
  EXPECT_EQ(e, "msg: RVL value longer than 33 bits (a damaged stream)");
  e = depth_error({1, 2, 3}, "16UC1; compressedDepth png");
  EXPECT_EQ(e, "msg: compressedDepth of 3 bytes has no header");
  e = depth_error(with_header({1, 2, 3}), "rgb8; compressedDepth png");
  EXPECT_EQ(e, "msg: compressedDepth of encoding 'rgb8' (16UC1, mono16 or 32FC1 are depth)");
  e = depth_error(with_header({1, 2, 3}), "16UC1; compressedDepth zstd");
  EXPECT_EQ(e, "msg: compressedDepth compression ' zstd' (png or rvl are read)");
  e = depth_error(with_header({1, 2, 3}), "16UC1; compressedDepth png");
  EXPECT_EQ(e.rfind("msg: ", 0), 0u) << e;  // the PNG decoder's own words
  std::vector<std::uint8_t> colour_png = png_of(cv::Mat3b(4, 4, cv::Vec3b(1, 2, 3)));
  e = depth_error(with_header(colour_png), "16UC1; compressedDepth png");
  EXPECT_EQ(e, "msg: compressedDepth PNG is not 16-bit grey");
  colour_png.resize(colour_png.size() / 2);
  e = test::error_message([&] { decode_compressed_colour("msg", "png", colour_png.data(), colour_png.size()); });
  EXPECT_EQ(e, "msg: compressed colour image cannot be decoded");
  e = test::error_message([&] { decode_compressed_colour("msg", "16UC1; compressedDepth png", nullptr, 0); });
  EXPECT_EQ(e, "msg: format '16UC1; compressedDepth png' is depth, not colour");
  e = test::error_message([&] { decode_compressed_colour("msg", "rgb8; webp compressed bgr8", nullptr, 0); });
  EXPECT_EQ(e, "msg: compressed colour format 'rgb8; webp compressed bgr8' (jpeg or png are read)");
}
