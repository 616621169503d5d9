#pragma once
// What the pipeline makes of a list of frames, for tests that compare runs (thread counts, options), and
// what a model detects in a recording, for tests that count it as the evaluation does.
#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/evaluation/detection_metrics.hpp"
#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/pipeline/parallel_pipeline.hpp"
#include "rdsf/pipeline/people_detector.hpp"
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

/// Every detection (box, H) of the frames of `source` by a fresh PeopleDetector of `model_path` (its own tracks),
/// per frame in source order, for detection_figures.
inline std::vector<FrameCandidates> detections_of(const std::string& model_path, const std::string& source) {
  PeopleDetector detector(model_path);
  auto frames_in = open_frame_source(source);
  std::vector<FrameCandidates> frames;
  DepthFrame frame;
  while (frames_in->next(frame)) {
    FrameCandidates& f = frames.emplace_back();
    f.frame = frame.name;
    for (const Detection& d : detector.detect(frame)) f.candidates.push_back({d.box, d.score, {}});
  }
  return frames;
}

}  // namespace rdsf::test
