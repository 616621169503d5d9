#pragma once
// Pictures of what the core did, for people: the depth layers in distinct colours with the candidates'
// boxes drawn on top. Pure drawing (imgproc); showing or saving is the programs' business.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/candidates/candidate.hpp"
#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/segmentation/depth_layers.hpp"

namespace rdsf {

/// A colour per layer (nearest warm, farthest cool), black for no reading, blended with the colour image
/// when the frame has one.
cv::Mat3b render_layers(const DepthFrame& frame, const Segmentation& segmentation);

/// Depth as a colour map (near = warm), black where there is no reading.
cv::Mat3b colourise_depth(const cv::Mat1w& depth_mm, int max_depth_mm = 8000);

/// Where a label of size `text` (cv::getTextSize) goes for `box` in an image of size `image`: its baseline
/// `above` pixels over the box's top (at least the text's height + 4 below the image's top), starting at the
/// box's left edge, moved left as far as needed so that the whole label stays in the image (a person at the
/// right border keeps a readable label), never left of x = 2.
cv::Point label_origin(const cv::Rect& box, const cv::Size& text, const cv::Size& image, int above);

/// Labels that do not cover each other, for one picture: place() puts a label where label_origin() does and,
/// while it would overlap a label placed before, one line lower (its height and baseline + 5 pixels), as
/// long as it stays in the image; where no line is free it stays at label_origin()'s place. A label's
/// rectangle is its text with 2 pixels each side, 3 above and baseline + 2 below the origin.
class LabelPlacer {
 public:
  explicit LabelPlacer(cv::Size image) : image_(image) {}
  /// The origin (cv::putText's bottom-left) of a label of size `text` and `baseline` for `box`.
  cv::Point place(const cv::Rect& box, const cv::Size& text, int baseline, int above);
  /// The rectangle a label of size `text` and `baseline` covers at `origin`.
  static cv::Rect area(cv::Point origin, const cv::Size& text, int baseline);

 private:
  cv::Size image_;
  std::vector<cv::Rect> placed_;
};

/// render_layers() with each candidate's reported box (`box`: solid), its window (thin), and a label with
/// its index, layer depth and, when `scores` is given, its score.
cv::Mat3b render_candidates(const DepthFrame& frame, const Segmentation& segmentation,
                            const std::vector<Candidate>& candidates, const std::vector<double>* scores = nullptr,
                            BoxKind box = BoxKind::fitted);

}  // namespace rdsf
