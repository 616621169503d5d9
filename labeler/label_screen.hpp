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
  std::optional<long> model_positives, model_negatives;  ///< answered by the model (with a model)
  std::optional<long> model_track_labels;  ///< labelled along the tracks of the model's answers (per track)
  std::optional<double> probability;                     ///< P(person)
  std::string reason;  ///< why this candidate is asked, e.g. "uncertain: P = 0.48"
  double zoom = 1.0;   ///< frame zoom around the candidate (+ / -), at most what keeps its window whole
  double rate_per_minute = 0;
  std::optional<double> score;
  std::optional<double> truth_iou;
  std::string message;  ///< e.g. "undone: 000012 #2"
};

/// A line of text on a small dark picture (shown while the session is scored).
cv::Mat3b render_note(const std::string& text);

/// The frame enlarged `zoom` times around `box` (kept inside the frame), at the frame's size.
cv::Mat3b zoom_around(const cv::Mat3b& view, const cv::Rect& box, double zoom);

cv::Mat3b render_label_screen(const PresentedCandidate& presented, const ScreenStatus& status);

/// `screen` with the strip of the track one answer to `asked` would label (`track`, frame order, asked not
/// among them) below it (gui/track_strip.hpp), and below that, when `place` is not empty, the strip of the
/// candidates of other frames an n labels at the same place beyond its track (one answer per place);
/// `screen` itself when both are empty.
cv::Mat3b add_track_strip(const cv::Mat3b& screen, const PresentedCandidate& asked,
                          const std::vector<PresentedCandidate>& track,
                          const std::vector<PresentedCandidate>& place = {});

}  // namespace rdsf
