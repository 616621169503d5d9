#pragma once
// Hand-built depth maps whose segmentation, candidates and features can be worked out by hand.
#include <filesystem>
#include <random>
#include <string>

#include <opencv2/core.hpp>

#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/frame/depth_png.hpp"

namespace rdsf::test {

/// Masked person-like crops: background 0, a body with a ragged edge at 1.5-4 m, holes and odd readings.
inline cv::Mat1w person_crop(unsigned seed) {
  std::mt19937 random(seed);
  cv::Mat1w crop(128, 64, std::uint16_t{0});
  const int depth = 1500 + static_cast<int>(random() % 2500);
  for (int y = 4; y < 126; ++y) {
    const int half = (y < 24 ? 7 : 15) + static_cast<int>(random() % 4);
    for (int x = 32 - half; x < 32 + half; ++x) {
      crop(y, x) = static_cast<std::uint16_t>(depth + (x - 32) * (x - 32) / 2 + static_cast<int>(random() % 40));
      if (random() % 23 == 0) crop(y, x) = 0;
    }
  }
  return crop;
}

/// A 640x480 frame filled with `wall_mm` (Kinect v1 camera, no colour).
inline DepthFrame wall_frame(int wall_mm) {
  DepthFrame frame;
  frame.depth_mm = cv::Mat1w(480, 640, static_cast<std::uint16_t>(wall_mm));
  frame.name = "hand";
  return frame;
}

/// Paints a rectangle of constant depth.
inline void paint(DepthFrame& frame, const cv::Rect& box, int depth_mm) {
  frame.depth_mm(box & cv::Rect(0, 0, frame.depth_mm.cols, frame.depth_mm.rows)).setTo(depth_mm);
}

/// Writes `folder`/a.depth.png and b.depth.png, two frames of three candidates each, in this order: the
/// person (nearest layer), the wall left of it, the wall right of it.
inline void write_two_person_frames(const std::string& folder) {
  std::filesystem::create_directories(folder);
  DepthFrame a = wall_frame(4000);
  paint(a, {300, 100, 40, 360}, 2000);
  write_png_atomically(folder + "/a.depth.png", a.depth_mm);
  DepthFrame b = wall_frame(4500);
  paint(b, {200, 80, 40, 380}, 2500);
  write_png_atomically(folder + "/b.depth.png", b.depth_mm);
}

}  // namespace rdsf::test
