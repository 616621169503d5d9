#pragma once
// Hand-built depth maps whose segmentation, candidates and features can be worked out by hand.
#include <opencv2/core.hpp>

#include "frame/depth_frame.hpp"

namespace rdsf::test {

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

}  // namespace rdsf::test
