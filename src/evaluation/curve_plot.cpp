#include "rdsf/evaluation/curve_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <opencv2/imgproc.hpp>

namespace rdsf {
namespace {

// Ten colours that stay apart (BGR): blue, orange, green, red, purple, gold, grey, brown, pink, teal; the
// quality report's eight lever models each get their own.
const cv::Scalar kPalette[] = {{200, 90, 20},  {30, 120, 230}, {60, 170, 60},  {40, 40, 200},  {170, 80, 160},
                               {30, 170, 200}, {90, 90, 90},   {40, 80, 140},  {190, 130, 240}, {150, 150, 20}};
// Curve i's colour (the palette repeats).
const cv::Scalar& palette(std::size_t i) { return kPalette[i % (sizeof kPalette / sizeof kPalette[0])]; }
const cv::Scalar kInk(40, 40, 40);
const cv::Scalar kGrid(225, 225, 225);

struct Frame {
  cv::Rect area;
  PlotAxes axes;
  double tx(double x) const {
    const double lo = axes.log_x ? std::log10(axes.x_min) : axes.x_min;
    const double hi = axes.log_x ? std::log10(axes.x_max) : axes.x_max;
    const double v = axes.log_x ? std::log10(std::max(x, axes.x_min)) : x;
    return area.x + (std::clamp(v, lo, hi) - lo) / (hi - lo) * area.width;
  }
  double ty(double y) const {
    const double lo = axes.log_y ? std::log10(axes.y_min) : axes.y_min;
    const double hi = axes.log_y ? std::log10(axes.y_max) : axes.y_max;
    const double v = axes.log_y ? std::log10(std::max(y, axes.y_min)) : y;
    return area.y + area.height - (std::clamp(v, lo, hi) - lo) / (hi - lo) * area.height;
  }
  cv::Point at(double x, double y) const {
    return {static_cast<int>(std::lround(tx(x))), static_cast<int>(std::lround(ty(y)))};
  }
};

std::vector<double> ticks(double lo, double hi, bool log) {
  std::vector<double> out;
  if (log) {
    for (double p = std::floor(std::log10(lo)); p <= std::ceil(std::log10(hi)) + 1e-9; p += 1) {
      const double v = std::pow(10.0, p);
      if (v >= lo * 0.999 && v <= hi * 1.001) out.push_back(v);
    }
    return out;
  }
  const double span = hi - lo;
  const double raw = span / 5;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (raw <= m * magnitude) {
      step = m * magnitude;
      break;
    }
  }
  for (double v = std::ceil(lo / step) * step; v <= hi + step * 1e-6; v += step) out.push_back(std::abs(v) < 1e-12 ? 0 : v);
  return out;
}

std::string format(double v) {
  char text[32];
  if (std::abs(v) >= 100000) {
    std::snprintf(text, sizeof text, "%.0e", v);
  } else {
    std::snprintf(text, sizeof text, "%g", v);
  }
  return text;
}

void text(cv::Mat3b& image, const std::string& s, cv::Point at, double scale, const cv::Scalar& colour,
          int thickness = 1) {
  cv::putText(image, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, thickness, cv::LINE_AA);
}

cv::Size text_size(const std::string& s, double scale, int thickness = 1) {
  int baseline = 0;
  return cv::getTextSize(s, cv::FONT_HERSHEY_SIMPLEX, scale, thickness, &baseline);
}

}  // namespace

cv::Mat3b draw_plot(const PlotAxes& axes, const std::vector<PlotCurve>& curves, cv::Size size) {
  cv::Mat3b image(size, cv::Vec3b(255, 255, 255));
  Frame frame{cv::Rect(90, 60, size.width - 120, size.height - 140), axes};

  // Grid and ticks.
  for (double x : ticks(axes.x_min, axes.x_max, axes.log_x)) {
    const int px = static_cast<int>(std::lround(frame.tx(x)));
    cv::line(image, {px, frame.area.y}, {px, frame.area.br().y}, kGrid, 1);
    const std::string label = format(x);
    text(image, label, {px - text_size(label, 0.45).width / 2, frame.area.br().y + 20}, 0.45, kInk);
  }
  for (double y : ticks(axes.y_min, axes.y_max, axes.log_y)) {
    const int py = static_cast<int>(std::lround(frame.ty(y)));
    cv::line(image, {frame.area.x, py}, {frame.area.br().x, py}, kGrid, 1);
    const std::string label = format(y);
    text(image, label, {frame.area.x - 10 - text_size(label, 0.45).width, py + 5}, 0.45, kInk);
  }
  cv::rectangle(image, frame.area, kInk, 1);

  // Titles.
  text(image, axes.title, {(size.width - text_size(axes.title, 0.7, 2).width) / 2, 35}, 0.7, kInk, 2);
  text(image, axes.x_label, {frame.area.x + (frame.area.width - text_size(axes.x_label, 0.55).width) / 2,
                             size.height - 30}, 0.55, kInk);
  cv::Mat3b y_label(40, std::max(1, text_size(axes.y_label, 0.55).width + 10), cv::Vec3b(255, 255, 255));
  text(y_label, axes.y_label, {5, 28}, 0.55, kInk);
  cv::Mat3b rotated;
  cv::rotate(y_label, rotated, cv::ROTATE_90_COUNTERCLOCKWISE);
  const int y0 = std::max(0, frame.area.y + (frame.area.height - rotated.rows) / 2);
  if (y0 + rotated.rows <= size.height && rotated.cols <= size.width) {
    rotated.copyTo(image(cv::Rect(8, y0, rotated.cols, rotated.rows)));
  }

  // Curves and operating points, then the legend on top of them. When every operating point has the same
  // label (the usual case: one probability threshold for all models), the legend says it once; otherwise
  // each point has its own, each curve's one line lower than the previous curve's (the points of similar
  // models lie close together).
  std::string shared_label;
  bool labels_differ = false;
  for (const PlotCurve& curve : curves) {
    if (!curve.operating_point || curve.operating_label.empty()) continue;
    if (shared_label.empty()) {
      shared_label = curve.operating_label;
    } else if (curve.operating_label != shared_label) {
      labels_differ = true;
    }
  }
  if (labels_differ) shared_label.clear();
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const PlotCurve& curve = curves[i];
    const cv::Scalar colour = palette(i);
    std::vector<cv::Point> polyline;
    for (const cv::Point2d& p : curve.points) polyline.push_back(frame.at(p.x, p.y));
    if (polyline.size() > 1) cv::polylines(image, polyline, false, colour, 2, cv::LINE_AA);
    for (const cv::Point& p : polyline) cv::circle(image, p, 3, colour, cv::FILLED, cv::LINE_AA);
    if (curve.operating_point) {
      const cv::Point p = frame.at(curve.operating_point->x, curve.operating_point->y);
      cv::drawMarker(image, p, colour, cv::MARKER_DIAMOND, 18, 2, cv::LINE_AA);
      if (!curve.operating_label.empty() && shared_label.empty()) {
        text(image, curve.operating_label, p + cv::Point(12, 16 * static_cast<int>(i) - 8), 0.45, colour);
      }
    }
  }
  const int rows = static_cast<int>(curves.size()) + (shared_label.empty() ? 0 : 1), box_w = 230,
            box_h = 22 * rows + 8;
  if (rows > 0) {
    const bool left = axes.legend == PlotAxes::Corner::bottom_left;
    const bool bottom = axes.legend != PlotAxes::Corner::top_right;
    const cv::Rect box(left ? frame.area.x + 10 : frame.area.br().x - box_w - 10,
                       bottom ? frame.area.br().y - box_h - 10 : frame.area.y + 10, box_w, box_h);
    cv::rectangle(image, box, cv::Scalar(255, 255, 255), cv::FILLED);
    cv::rectangle(image, box, cv::Scalar(200, 200, 200), 1);
    for (int i = 0; i < static_cast<int>(curves.size()); ++i) {
      const cv::Scalar colour = palette(static_cast<std::size_t>(i));
      const int y = box.y + 22 * (i + 1);
      cv::line(image, {box.x + 10, y - 5}, {box.x + 40, y - 5}, colour, 3, cv::LINE_AA);
      text(image, curves[static_cast<std::size_t>(i)].label, {box.x + 48, y}, 0.5, kInk);
    }
    if (!shared_label.empty()) {
      const int y = box.y + 22 * rows;
      cv::drawMarker(image, {box.x + 25, y - 5}, kInk, cv::MARKER_DIAMOND, 14, 2, cv::LINE_AA);
      text(image, "operating point, " + shared_label, {box.x + 48, y}, 0.5, kInk);
    }
  }
  return image;
}

}  // namespace rdsf
