#include "rdsf/pipeline/people_overlay.hpp"

#include <cstdio>

#include <opencv2/imgproc.hpp>

#include "rdsf/analysis/overlay.hpp"

namespace rdsf {

cv::Mat3b render_people(const DepthFrame& frame, const PipelineFrame& processed, const Tracker& tracker,
                        BoxKind kind) {
  cv::Mat3b picture = frame.has_colour() ? frame.bgr.clone() : colourise_depth(frame.depth_mm);
  cv::addWeighted(picture, 0.75, render_layers(frame, processed.analysis.segmentation), 0.25, 0.0, picture);
  const auto& candidates = processed.analysis.candidates;
  char text[96];
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (processed.person[i] != 0) continue;
    const cv::Rect& box = reported_box(candidates[i], kind);
    cv::rectangle(picture, box, cv::Scalar(170, 170, 170), 1, cv::LINE_AA);
    if (i < processed.probabilities.size()) {
      std::snprintf(text, sizeof text, "%.2f", processed.probabilities[i]);
      cv::putText(picture, text, box.tl() + cv::Point(3, 14), cv::FONT_HERSHEY_SIMPLEX, 0.4,
                  cv::Scalar(200, 200, 200), 1, cv::LINE_AA);
    }
  }
  LabelPlacer labels(picture.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const int id = processed.person[i];
    if (id == 0) continue;
    const TrackedPerson* person = tracker.person(id);
    const cv::Scalar colour = person != nullptr ? person->colour : cv::Scalar(0, 255, 0);
    const cv::Rect& box = reported_box(candidates[i], kind);
    cv::rectangle(picture, box, colour, 3, cv::LINE_AA);
    std::snprintf(text, sizeof text, "person %d  %.2f m walked  P=%.2f", id,
                  person != nullptr ? person->distance_cm / 100.0 : 0.0,
                  i < processed.probabilities.size() ? processed.probabilities[i] : 0.0);
    int baseline = 0;
    const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, 0.5, 1, &baseline);
    const cv::Point at = labels.place(box, size, baseline, 6);
    cv::rectangle(picture, at + cv::Point(-2, baseline + 2), at + cv::Point(size.width + 2, -size.height - 3), colour,
                  cv::FILLED);
    cv::putText(picture, text, at, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  }
  return picture;
}

}  // namespace rdsf
