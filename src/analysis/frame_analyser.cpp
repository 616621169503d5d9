#include "rdsf/analysis/frame_analyser.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {
AnalyserParams thesis_params(AnalyserParams params) {
  params.segmentation.left_border_jump = false;
  params.reported_box = BoxKind::strict;
  CandidateParams& c = params.candidates;
  c.occlusion_gap_cm = 0;
  c.floor_tolerance_mm = 0;
  c.height_at_column_depth = false;
  c.fit_reach_cm = 0;
  c.fit_occlusion_gap_cm = 0;
  c.fit_min_width_ratio = 0;
  c.join_pieces = false;
  c.max_object_width_cm = 0;
  c.min_fitted_width_cm = 0;
  c.narrow_fitted_width_cm = 0;
  c.split_depth_jump_mm = 0;
  c.split_valley_cm = 0;
  c.split_step_cm = 0;
  c.split_head_drop_cm = 0;
  c.fit_across_head_cut = false;
  c.split_keep_whole = false;
  return params;
}

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
  FrameAnalysis analysis;
  auto start = std::chrono::steady_clock::now();
  const AnalyserParams p = params_for_camera(params_, frame.camera);
  analysis.segmentation = segment_depth(frame.depth_mm, p.segmentation);
  analysis.times.segmentation_ms = milliseconds_since(start);

  start = std::chrono::steady_clock::now();
  const cv::Size crop(params_.features.window_width_px, params_.features.window_height_px);
  analysis.candidates = find_candidates(frame, analysis.segmentation, p.candidates, crop, colour);
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
