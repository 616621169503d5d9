#pragma once
// Whether a frame's readings look like millimetres of a Kinect-class camera. A 16-bit depth PNG states no
// unit, so depth in another one is read without complaint: TUM RGB-D's 5000 units a metre read five times
// too far, a sensor's 0.1 mm units ten times, centimetres ten times too near. camera.yml's depth_unit_mm
// (frame/camera_file.hpp) is how another unit is stated.
//   plausible: kMinMedianReadingMm <= the median of the frame's nonzero readings <= kMaxMedianReadingMm
// (a room's median is 1-5 m; a close-up or a hall stays inside). rdsf-detect prints depth_units_note() once,
// for the first frame with readings, and goes on; rdsf-adapt refuses a room outside the range before it
// trains on it (adapt_run.cpp).
#include <cmath>
#include <cstdint>
#include <string>

#include <opencv2/core.hpp>

namespace rdsf {

constexpr int kMinMedianReadingMm = 300;
constexpr int kMaxMedianReadingMm = 12000;

/// A reading in metres (a 32FC1 depth image's, REP 118) in millimetres: round(1000 m) to the nearest, ties to
/// even (so a millimetre depth written as float32 metres reads back exactly); NaN, inf, <= 0 and > 65535 mm
/// are no reading (0). The one conversion of the bag source, its compressed depth and the ROS node.
inline std::uint16_t depth_mm_of_metres(float metres) {
  const double mm = std::isfinite(metres) ? std::nearbyint(1000.0 * static_cast<double>(metres)) : 0.0;
  return mm > 0 && mm <= 65535 ? static_cast<std::uint16_t>(mm) : 0;
}

/// A reading of `unit_mm` millimetres a unit in millimetres: round(units x unit_mm), ties to even; over
/// 65535 mm is no reading (0).
inline std::uint16_t depth_mm_of_units(std::uint16_t units, double unit_mm) {
  const double mm = std::nearbyint(units * unit_mm);
  return mm <= 65535 ? static_cast<std::uint16_t>(mm) : 0;
}

/// The median of the frame's nonzero readings (the upper one of an even count); 0 when it has none.
int median_reading_mm(const cv::Mat1w& depth_mm);

/// The range above: kMinMedianReadingMm <= median_mm <= kMaxMedianReadingMm.
inline bool plausible_median_reading_mm(int median_mm) {
  return median_mm >= kMinMedianReadingMm && median_mm <= kMaxMedianReadingMm;
}

/// Empty when the frame has no reading or its median is plausible (above); else one sentence naming the
/// median and how to state another unit.
std::string depth_units_note(const cv::Mat1w& depth_mm);

}  // namespace rdsf
