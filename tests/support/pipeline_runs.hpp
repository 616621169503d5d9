#pragma once
// What the pipeline makes of a list of frames, for tests that compare runs (thread counts, options).
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/pipeline/parallel_pipeline.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"

namespace rdsf::test {

/// Per frame, in frame order, each candidate's fitted box and whether it is a foreground one
/// (Candidate::foreground).
using CandidateBoxes = std::vector<std::vector<std::pair<cv::Rect, bool>>>;

/// The candidates of PeoplePipeline(params, no model) over `frames` on `threads` threads.
inline CandidateBoxes candidate_boxes(const PipelineParams& params, const std::vector<DepthFrame>& frames, int threads) {
  PeoplePipeline pipeline(params, nullptr);
  CandidateBoxes found;
  run_in_frame_order(pipeline, static_cast<std::int64_t>(frames.size()),
                     [&](std::int64_t i) { return frames[static_cast<std::size_t>(i)]; }, {threads, 0, 0},
                     [&](const DepthFrame&, PipelineFrame& r) {
                       found.emplace_back();
                       for (const Candidate& c : r.analysis.candidates) found.back().emplace_back(c.fitted_box, c.foreground);
                       return true;
                     });
  return found;
}

/// How many of `boxes` are foreground candidates.
inline std::size_t foreground_count(const CandidateBoxes& boxes) {
  std::size_t n = 0;
  for (const auto& frame : boxes) n += static_cast<std::size_t>(std::count_if(frame.begin(), frame.end(), [](const auto& c) { return c.second; }));
  return n;
}

}  // namespace rdsf::test
