#pragma once
// Line charts for ROC and DET curves, drawn with OpenCV's imgproc (no window): axes with ticks and grid,
// linear or logarithmic, one colour per curve, a legend, and a marked operating point per curve.
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf {

struct PlotCurve {
  std::string label;
  std::vector<cv::Point2d> points;          ///< in data units, drawn in the given order
  std::optional<cv::Point2d> operating_point;
  std::string operating_label;              ///< e.g. "T=0"
};

struct PlotAxes {
  std::string title, x_label, y_label;
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;
  bool log_x = false, log_y = false;        ///< log axes clamp values below the minimum to the minimum
  /// The legend's corner, drawn last on a white box: where the curves are not (a ROC curve rises to the top
  /// left and runs along the top, so bottom right; a DET curve falls from top left to bottom right).
  enum class Corner { top_right, bottom_left, bottom_right };
  Corner legend = Corner::bottom_right;
};

cv::Mat3b draw_plot(const PlotAxes& axes, const std::vector<PlotCurve>& curves, cv::Size size = {900, 650});

}  // namespace rdsf
