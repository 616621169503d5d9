#pragma once
// Shared by the test_openni_* programs: a known PNG sequence for the virtual sensor (rdsf-png://), a way
// to record it with rdsf-record, and checks that a frame equals its PNG exactly.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/core/error.hpp"
#include "rdsf/frame/depth_png.hpp"
#include "support/test_support.hpp"

namespace rdsf::test::openni {

/// Depth of frame `i`: a gradient that differs at every pixel and frame, with a block of no-reading (0)
/// and a block at the far end of the range, so both ends of the 16-bit values go through the codec.
inline cv::Mat1w depth_for(int i, cv::Size size = {640, 480}) {
  cv::Mat1w depth(size);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      depth(y, x) = static_cast<std::uint16_t>(500 + (x * 7 + y * 13 + i * 101) % 7500);
    }
  }
  depth(cv::Rect(10 + i, 20, 40, 30)).setTo(0);
  depth(cv::Rect(300, 200 + i, 20, 20)).setTo(9999);
  return depth;
}

/// Colour of frame `i` (BGR), different in each channel and frame.
inline cv::Mat3b colour_for(int i, cv::Size size = {640, 480}) {
  cv::Mat3b bgr(size);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      bgr(y, x) = cv::Vec3b(static_cast<std::uint8_t>(x + i), static_cast<std::uint8_t>(y * 3),
                            static_cast<std::uint8_t>(i * 37 + x / 3));
    }
  }
  return bgr;
}

inline std::string frame_stem(int i) {
  char stem[32];
  std::snprintf(stem, sizeof stem, "frame%04d", i);
  return stem;
}

/// Writes `count` frames NAME.depth.png (and NAME.rgb.png with `colour`) of `size` into `folder`.
inline void write_sequence(const std::string& folder, int count, bool colour, cv::Size size = {640, 480}) {
  for (int i = 0; i < count; ++i) {
    write_png_atomically(folder + "/" + frame_stem(i) + ".depth.png", depth_for(i, size));
    if (colour) write_png_atomically(folder + "/" + frame_stem(i) + ".rgb.png", colour_for(i, size));
  }
}

inline std::string device_uri(const std::string& folder, const std::string& options = {}) {
  return "rdsf-png://" + folder + (options.empty() ? "" : "?" + options);
}

/// Runs rdsf-record with `arguments` appended.
inline RunResult record(const std::string& arguments) {
  return run(quote(program("rdsf-record")) + " " + arguments);
}

inline bool identical(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != b.type()) return false;
  cv::Mat differs;
  cv::compare(a.reshape(1), b.reshape(1), differs, cv::CMP_NE);
  return cv::countNonZero(differs) == 0;
}

/// Expects `body` to throw an Error whose message is one line and contains every part.
template <typename F>
void expect_error(F body, const std::vector<std::string>& parts) {
  try {
    body();
    ADD_FAILURE() << "no error thrown";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    for (const std::string& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

}  // namespace rdsf::test::openni
