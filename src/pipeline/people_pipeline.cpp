#include "rdsf/pipeline/people_pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "rdsf/candidates/duplicate_candidates.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/pipeline/model_fit.hpp"

namespace rdsf {

std::string PipelineParams::decision_text(const BoostedModel& model) const {
  char text[96];
  if (score_threshold) {
    std::snprintf(text, sizeof text, "people at H(x) >= %.2f", *score_threshold);
  } else {
    const bool stated = probability_threshold <= 0.0 && model.operating_point();
    std::snprintf(text, sizeof text, "people at P >= %.2f%s", probability_threshold_for(model),
                  stated ? " (its operating point)" : "");
  }
  std::string out = text;
  if (max_person_height_cm > 0.0) {
    std::snprintf(text, sizeof text, ", none taller than %.0f cm", max_person_height_cm);
    out += text;
  }
  return out;
}

bool PipelineParams::mirror_average_for(const BoostedModel& model) const {
  return mirror_average && !model.training().adapted_to_a_room();
}

std::size_t PipelineParams::inherited_mirror_rounds_for(const BoostedModel& model) const {
  if (!mirror_average || !mirror_average_inherited || mirror_average_for(model)) return 0;
  return std::min(model.training().inherited_weak_classifiers(), model.weak_classifiers().size());
}

namespace {

// The analyser's parameters with the detector's height limit (PipelineParams::max_person_height_cm).
AnalyserParams with_height_limit(AnalyserParams analyser, double max_person_height_cm) {
  analyser.candidates.max_height_cm = max_person_height_cm;
  return analyser;
}

// `params` with the analyser options `model` runs with (stated_options.hpp).
PipelineParams running(PipelineParams params, const BoostedModel* model) {
  params.analyser = params.analyser_given.for_model(params.analyser, model);
  return params;
}

}  // namespace

PeoplePipeline::PeoplePipeline(PipelineParams params, const BoostedModel* model)
    : params_(running(std::move(params), model)), model_(model),
      analyser_(with_height_limit(params_.analyser, params_.max_person_height_cm)), tracker_(params_.tracking) {
  if (model_ == nullptr) return;
  check_model_fits(*model_, params_.analyser);
  scorer_.emplace(*model_);
  mirror_.emplace(*model_, params_);
}

PipelineFrame PeoplePipeline::process(const DepthFrame& frame) {
  PipelineFrame out = analyse(frame);
  track(frame, out);
  return out;
}

PipelineFrame PeoplePipeline::analyse(const DepthFrame& frame) const {
  if (frame.depth_mm.empty()) fail("frame " + frame.name, "has no depth image");
  if (frame.depth_mm.cols != frame.camera.width_px || frame.depth_mm.rows != frame.camera.height_px) {
    fail("frame " + frame.name, std::to_string(frame.depth_mm.cols) + "x" + std::to_string(frame.depth_mm.rows) +
                                    " depth image, but its camera model is " + frame.camera.describe() +
                                    " (give the camera model of this image size)");
  }
  PipelineFrame out;
  const bool full = model_ != nullptr && params_.full_feature_vector;
  out.analysis = analyser_.analyse(frame, full, params_.colour_crops_of_all ? CropColour::cut : CropColour::later);
  out.times = out.analysis.times;
  const std::size_t n = out.analysis.candidates.size();
  out.person.assign(n, 0);
  if (model_ == nullptr) return out;

  auto start = std::chrono::steady_clock::now();
  if (full) {
    out.scores = model_->score(out.analysis.features);
    mirror_->apply(*scorer_, out.analysis.candidates, cv::Mat1f(), cv::Mat1f(), out.scores);
  } else {
    // The features the model reads, of each crop and (when the scores read it) of its mirror, in one pass.
    cv::Mat1f mirror_features;
    scorer_->compute(out.analysis.candidates, out.model_features, mirror_->reads_mirror() ? &mirror_features : nullptr);
    out.times.features_ms = milliseconds_since(start);
    start = std::chrono::steady_clock::now();
    out.scores = scorer_->score_rows(out.model_features);
    mirror_->apply(*scorer_, out.analysis.candidates, out.model_features, mirror_features, out.scores);
  }
  for (double h : out.scores) out.probabilities.push_back(model_->probability(h));
  std::vector<CandidateKin> kin;
  for (const Candidate& c : out.analysis.candidates) kin.push_back(params_.suppress_duplicates ? kin_of(c) : CandidateKin{});
  out.duplicate = duplicate_candidates(kin, out.scores);
  out.times.classifier_ms = milliseconds_since(start);

  start = std::chrono::steady_clock::now();
  const double threshold = params_.score_threshold_for(*model_);
  out.histograms.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (out.scores[i] < threshold || out.duplicate[i] != 0) continue;
    Candidate& c = out.analysis.candidates[i];
    if (!params_.colour_crops_of_all) {
      cut_colour_crop(frame, c.foreground ? out.analysis.in_front.labels : out.analysis.segmentation.labels, c);
    }
    out.histograms[i] = ColourHistogram::of(c.colour_crop, c.depth_crop, params_.tracking.histogram_bins);
  }
  out.times.tracking_ms = milliseconds_since(start);
  return out;
}

void PeoplePipeline::track(const DepthFrame& frame, PipelineFrame& out) {
  if (model_ == nullptr) return;
  const auto start = std::chrono::steady_clock::now();
  const double threshold = params_.score_threshold_for(*model_);
  std::vector<TrackInput> detections;
  std::vector<std::size_t> which;
  for (std::size_t i = 0; i < out.scores.size(); ++i) {
    if (out.scores[i] < threshold || out.duplicate[i] != 0) continue;
    const Candidate& c = out.analysis.candidates[i];
    detections.push_back({reported_box(c, params_.analyser.reported_box), c.layer_depth_mm, out.histograms[i]});
    which.push_back(i);
  }
  const std::vector<int> ids = tracker_.update(detections, frame.camera, frame.index);
  for (std::size_t k = 0; k < which.size(); ++k) out.person[which[k]] = ids[k];
  out.times.tracking_ms += milliseconds_since(start);
}

}  // namespace rdsf
