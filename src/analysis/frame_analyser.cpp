#include "rdsf/analysis/frame_analyser.hpp"

#include <chrono>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {
const ParameterTable<AnalyserParams>& analyser_parameters() {
  using P = AnalyserParams;
  static const ParameterTable<P> table = [] {
    ParameterTable<P> t = joined(nested(segmentation_parameters(), &P::segmentation),
                                 nested(candidate_parameters(), &P::candidates));
    t.push_back(computed_parameter<P, std::string>(
        "box",
        "the box detections report and assisted labelling matches (CSV, pictures, tracking, evaluation): fitted "
        "(the object's extent) or strict (the thesis's height x height/2)",
        [](const P& p) { return std::string(p.reported_box == BoxKind::strict ? "strict" : "fitted"); },
        [](P& p, const std::string& box) {
          if (box != "fitted" && box != "strict") refuse_parameter("box", "is fitted or strict, not '" + box + "'");
          p.reported_box = box == "strict" ? BoxKind::strict : BoxKind::fitted;
        },
        std::string("strict")));
    return t;
  }();
  return table;
}

AnalyserParams thesis_params(AnalyserParams params) { return with_thesis_values(analyser_parameters(), params); }

FrameAnalyser::FrameAnalyser(AnalyserParams params) : params_(params), extractor_(params.features) {}

FrameAnalysis FrameAnalyser::analyse(const DepthFrame& frame, bool with_features, CropColour colour) const {
  if (frame.depth_mm.empty()) throw Error("frame " + frame.name + ": empty depth image");
  FrameAnalysis analysis;
  auto start = std::chrono::steady_clock::now();
  analysis.segmentation = segment_depth(frame.depth_mm, params_.segmentation);
  analysis.times.segmentation_ms = milliseconds_since(start);

  start = std::chrono::steady_clock::now();
  const cv::Size crop(params_.features.window_width_px, params_.features.window_height_px);
  analysis.candidates = find_candidates(frame, analysis.segmentation, params_.candidates, crop, colour);
  analysis.times.candidates_ms = milliseconds_since(start);

  if (with_features) {
    start = std::chrono::steady_clock::now();
    analysis.features = features(analysis.candidates);
    analysis.times.features_ms = milliseconds_since(start);
  }
  return analysis;
}

cv::Mat1f FrameAnalyser::features(const std::vector<Candidate>& candidates) const {
  cv::Mat1f rows(static_cast<int>(candidates.size()), extractor_.dimension());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    extractor_.compute(candidates[i].depth_crop, rows.ptr<float>(static_cast<int>(i)));
  }
  return rows;
}

}  // namespace rdsf
