#pragma once
// The picture of a processed frame for people: layers faint in the background, every candidate's strict box
// in grey with its score, and every detected person's box in the person's colour with their number and the
// distance they have covered.
#include <opencv2/core.hpp>

#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"

namespace rdsf {

cv::Mat3b render_people(const DepthFrame& frame, const PipelineFrame& processed, const Tracker& tracker,
                        BoxKind box = BoxKind::fitted);

}  // namespace rdsf
