#include "rdsf/analysis/overlay.hpp"

#include <algorithm>
#include <cstdio>

#include <opencv2/imgproc.hpp>

namespace rdsf {
namespace {

cv::Vec3b layer_colour(int index, int count) {
  // Hue from red (near) to blue (far), full saturation, in BGR.
  const double t = count > 1 ? static_cast<double>(index) / (count - 1) : 0.0;
  cv::Mat3b hsv(1, 1, cv::Vec3b(static_cast<std::uint8_t>(120 * t), 200, 255));
  cv::Mat3b bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  return bgr(0, 0);
}

}  // namespace

cv::Point label_origin(const cv::Rect& box, const cv::Size& text, const cv::Size& image, int above) {
  const int x = std::max(2, std::min(box.x + 2, image.width - text.width - 4));
  const int y = std::max(text.height + 4, box.y - above);
  return {x, y};
}

cv::Rect LabelPlacer::area(cv::Point origin, const cv::Size& text, int baseline) {
  return {origin.x - 2, origin.y - text.height - 3, text.width + 4, text.height + baseline + 5};
}

cv::Point LabelPlacer::place(const cv::Rect& box, const cv::Size& text, int baseline, int above) {
  const cv::Point first = label_origin(box, text, image_, above);
  const auto free = [&](cv::Point at) {
    const cv::Rect mine = area(at, text, baseline);
    return std::none_of(placed_.begin(), placed_.end(), [&](const cv::Rect& r) { return (r & mine).area() > 0; });
  };
  const cv::Point line(0, area(first, text, baseline).height);  // one line lower: the label's own height
  cv::Point at = first;
  while (!free(at) && area(at + line, text, baseline).br().y <= image_.height) at += line;
  if (!free(at)) at = first;
  placed_.push_back(area(at, text, baseline));
  return at;
}

cv::Mat3b colourise_depth(const cv::Mat1w& depth_mm, int max_depth_mm) {
  cv::Mat1b scaled;
  depth_mm.convertTo(scaled, CV_8U, -255.0 / max_depth_mm, 255.0);
  cv::Mat3b coloured;
  cv::applyColorMap(scaled, coloured, cv::COLORMAP_JET);
  coloured.setTo(cv::Scalar::all(0), depth_mm == 0);
  return coloured;
}

cv::Mat3b render_layers(const DepthFrame& frame, const Segmentation& segmentation) {
  const int count = static_cast<int>(segmentation.layers.size());
  std::vector<cv::Vec3b> palette(static_cast<std::size_t>(count) + 1, cv::Vec3b(0, 0, 0));
  for (int i = 0; i < count; ++i) palette[static_cast<std::size_t>(i) + 1] = layer_colour(i, count);
  cv::Mat3b picture(segmentation.labels.size());
  for (int r = 0; r < picture.rows; ++r) {
    const std::uint8_t* label = segmentation.labels.ptr<std::uint8_t>(r);
    cv::Vec3b* out = picture.ptr<cv::Vec3b>(r);
    for (int c = 0; c < picture.cols; ++c) out[c] = palette[label[c]];
  }
  if (frame.has_colour()) cv::addWeighted(picture, 0.55, frame.bgr, 0.45, 0.0, picture);
  return picture;
}

cv::Mat3b render_candidates(const DepthFrame& frame, const Segmentation& segmentation,
                            const std::vector<Candidate>& candidates, const std::vector<double>* scores,
                            BoxKind box) {
  cv::Mat3b picture = render_layers(frame, segmentation);
  LabelPlacer labels(picture.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Candidate& c = candidates[i];
    cv::rectangle(picture, c.window, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
    const cv::Rect& shown = reported_box(c, box);
    cv::rectangle(picture, shown, cv::Scalar(0, 255, 255), 2, cv::LINE_AA);
    char text[96];
    if (scores != nullptr && i < scores->size()) {
      std::snprintf(text, sizeof text, "#%zu %.1fm H=%.1f", i, c.layer_depth_mm / 1000.0, (*scores)[i]);
    } else {
      std::snprintf(text, sizeof text, "#%zu %.1fm", i, c.layer_depth_mm / 1000.0);
    }
    int baseline = 0;
    const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, 0.45, 3, &baseline);
    const cv::Point at = labels.place(shown, size, baseline, 4);
    cv::putText(picture, text, at, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 3, cv::LINE_AA);
    cv::putText(picture, text, at, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 255, 255), 1, cv::LINE_AA);
  }
  return picture;
}

}  // namespace rdsf
