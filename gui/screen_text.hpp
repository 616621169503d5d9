#pragma once
// The look the programs' screens share (rdsf-label, rdsf-review): colours and one way of writing text.
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace rdsf::gui {

inline const cv::Scalar kBackground(38, 34, 30);
inline const cv::Scalar kText(235, 235, 235);
inline const cv::Scalar kDim(150, 150, 150);
inline const cv::Scalar kHighlight(0, 215, 255);  // amber

inline void put(cv::Mat3b& canvas, const std::string& text, cv::Point at, double scale, const cv::Scalar& colour,
                int thickness = 1) {
  cv::putText(canvas, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, thickness, cv::LINE_AA);
}

}  // namespace rdsf::gui
