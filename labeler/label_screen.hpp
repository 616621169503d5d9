#pragma once
// What the labeler shows for one candidate: the whole frame (colour if present, else colourised depth)
// with the candidate's box and the other candidates faint; beside it the 64x128 depth crop enlarged (and
// the colour crop); below, a status line and the keys.
#include <string>

#include <opencv2/core.hpp>

#include "rdsf/labeling/labeling_session.hpp"

namespace rdsf {

struct ScreenStatus {
  std::int64_t frame_ordinal = 0;
  std::optional<std::int64_t> total_frames;
  std::size_t candidate = 0, candidates = 0;  ///< j/M in the frame (1-based j)
  long positives = 0, negatives = 0;
  double rate_per_minute = 0;
  std::optional<double> score;
  std::optional<double> truth_iou;
  std::string message;  ///< e.g. "undone: 000012 #2"
};

cv::Mat3b render_label_screen(const PresentedCandidate& presented, const ScreenStatus& status);

}  // namespace rdsf
