#include "rdsf/analysis/frame_analyser.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/candidates/foreground_candidates.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/frame_buffers.hpp"
#include "rdsf/segmentation/local_background.hpp"

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
    t.push_back(parameter("local-front", &P::local_front_reach_cm,
                          "without --background: add as candidates the objects nearer than their surroundings on "
                          "both sides along the row within this reach (cm; a person before a wall), by "
                          "--background-margin and --background-relative; 0 = off",
                          Range::between(0, 500), std::optional<double>(0.0)));
    t.push_back(parameter("reference-focal", &P::reference_focal_px,
                          "pixel counts (--row-step, --n, --k, --column-gap) are for a camera of this focal length "
                          "(px); other cameras get them scaled by fx or fy / this; 0 = as given",
                          Range::at_least(0)));
    return t;
  }();
  return table;
}

AnalyserParams thesis_params(AnalyserParams params) { return with_thesis_values(analyser_parameters(), params); }

AnalyserParams params_for_camera(const AnalyserParams& params, const CameraModel& camera) {
  if (!(params.reference_focal_px > 0) ||
      (camera.fx_px == params.reference_focal_px && camera.fy_px == params.reference_focal_px)) {
    return params;
  }
  const double sx = camera.fx_px / params.reference_focal_px, sy = camera.fy_px / params.reference_focal_px;
  const auto scaled = [](int pixels, double scale) { return std::max(1, static_cast<int>(std::lround(pixels * scale))); };
  AnalyserParams p = params;
  p.segmentation.n = scaled(params.segmentation.n, sx);
  p.segmentation.row_step = scaled(params.segmentation.row_step, sy);
  p.candidates.column_gap = scaled(params.candidates.column_gap, sx);
  p.candidates.k = scaled(params.candidates.k, sy);
  return p;
}

FrameAnalyser::FrameAnalyser(AnalyserParams params) : params_(params), extractor_(params.features) {}

FrameAnalysis FrameAnalyser::analyse(const DepthFrame& frame, bool with_features, CropColour colour) const {
  if (frame.depth_mm.empty()) throw Error("frame " + frame.name + ": empty depth image");
  if (params_.background) params_.background->check_fits(frame);
  FrameAnalysis analysis;
  auto start = std::chrono::steady_clock::now();
  const AnalyserParams p = params_for_camera(params_, frame.camera);
  analysis.segmentation = segment_depth(frame.depth_mm, p.segmentation);
  analysis.times.segmentation_ms = milliseconds_since(start);

  start = std::chrono::steady_clock::now();
  const cv::Size crop(params_.features.window_width_px, params_.features.window_height_px);
  analysis.candidates = find_candidates(frame, analysis.segmentation, p.candidates, crop, colour);
  if (params_.background || p.local_front_reach_cm > 0) {
    cv::Mat1w local_far_mm;
    if (!params_.background) {
      local_far_mm = frame_buffer(FrameBuffer::local_far, frame.depth_mm.size(), CV_16UC1);
      local_background(frame.depth_mm, frame.camera, p.local_front_reach_cm * 10.0, local_far_mm);
    }
    const cv::Mat1w& far_mm = params_.background ? params_.background->far_mm : local_far_mm;
    analysis.in_front = in_front_of(analysis.segmentation, frame.depth_mm, far_mm, params_.background_margins);
    add_foreground_candidates(frame, analysis.in_front, p.candidates, crop, colour, analysis.candidates);
  }
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
