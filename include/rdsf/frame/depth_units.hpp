#pragma once
// Whether a frame's readings look like millimetres of a Kinect-class camera. A 16-bit depth PNG states no
// unit, so depth in another one is read without complaint: TUM RGB-D's 5000 units a metre read five times
// too far, a sensor's 0.1 mm units ten times, centimetres ten times too near. camera.yml's depth_unit_mm
// (frame/camera_file.hpp) is how another unit is stated.
//   plausible: kMinMedianReadingMm <= the median of the frame's nonzero readings <= kMaxMedianReadingMm
// (a room's median is 1-5 m; a close-up or a hall stays inside). rdsf-detect prints depth_units_note() once,
// for the first frame with readings, and goes on; rdsf-adapt refuses a room outside the range before it
// trains on it (adapt_run.cpp).
#include <string>

#include <opencv2/core.hpp>

namespace rdsf {

constexpr int kMinMedianReadingMm = 300;
constexpr int kMaxMedianReadingMm = 12000;

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
