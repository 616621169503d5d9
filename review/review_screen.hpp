#pragma once
// What the review shows: a page of samples as a grid, each its depth crop (colourised) and colour crop
// side by side with its label, P(person) under the model, origin and id; the selected one framed in amber,
// flipped ones marked, retracted ones dimmed; below, a status line and the keys.
#include <string>

#include <opencv2/core.hpp>

#include "rdsf/labeling/review_session.hpp"

namespace rdsf {

cv::Mat3b render_review_screen(const ReviewSession& session, const std::string& message);

/// The frame a sample came from with its strict box, for the "open frame" key.
cv::Mat3b render_sample_frame(const DepthFrame& frame, const SampleRecord& record);

}  // namespace rdsf
