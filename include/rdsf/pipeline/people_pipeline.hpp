#pragma once
// The whole system for one frame, as the thesis ran it:
//   frame -> segmentation -> candidates -> RDSF -> classifier score H(x) and P(person)
//         -> person when P(person) >= probability_threshold (or H(x) >= score_threshold, the thesis's way)
//   (RDSF: only the features the model reads, see model_scorer.hpp)
//         -> tracking (colour histogram + centroid, lkh matching)
// with the time of every stage. Without a model, every candidate is reported unscored and nothing is tracked.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/core/parameter_table.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/pipeline/mirror_scoring.hpp"
#include "rdsf/pipeline/model_scorer.hpp"
#include "rdsf/pipeline/stated_options.hpp"
#include "rdsf/tracking/tracker.hpp"

namespace rdsf {

struct PipelineParams {
  /// The frame analyser's options. With a model that states detection options (stated_options.hpp), each
  /// option not among analyser_given's takes the model's value (PeoplePipeline's params() are the result).
  AnalyserParams analyser;
  /// The analyser options the user gave, which keep their values whatever the model states.
  GivenOptions analyser_given;
  TrackingParams tracking;
  /// A candidate is a person when P(person) >= this (the model's calibrated probability). 0 (default): the
  /// model's operating point (BoostedModel::operating_probability: the one it states, else 0.5).
  double probability_threshold = 0.0;
  /// When set, a candidate is a person when H(x) >= this instead: the thesis's threshold_classifier.
  std::optional<double> score_threshold;
  /// The P(person) threshold these mean for `model`: the score threshold's probability when one is given,
  /// else probability_threshold, or its operating point.
  double probability_threshold_for(const BoostedModel& model) const {
    if (score_threshold) return model.probability(*score_threshold);
    return probability_threshold > 0.0 ? probability_threshold : model.operating_probability();
  }
  /// The score threshold these mean for `model`.
  double score_threshold_for(const BoostedModel& model) const {
    return score_threshold ? *score_threshold : model.calibration().score_at(probability_threshold_for(model));
  }
  /// Where `model` is read, as the programs say it: "people at P >= 0.27 (its operating point)", "people at
  /// P >= 0.60" (a threshold given), "people at H(x) >= 0.00" (the thesis's score threshold); with the
  /// height limit on, ", none taller than 250 cm" follows.
  std::string decision_text(const BoostedModel& model) const;
  /// Compute every feature of every candidate, then score (the thesis's way, and analysis.features is
  /// filled). Off (default): only the features the model reads (ModelScorer), same scores bit for bit.
  bool full_feature_vector = false;
  /// A candidate's score is the mean of H(x) of its depth crop and of the crop mirrored left to right
  /// (ModelScorer::mirrored_score): a person seen from the other side is a person, and the models are
  /// trained with mirrored positives, so the mean keeps what both views agree on and halves what one view's
  /// noise alone adds. P(person) is the model's calibration of that mean. Twice the features per candidate
  /// (2.8 -> about 5.6 us). false: one crop, the thesis's way (--thesis turns it off). Measured with
  /// people/v2 (docs/quality.md, "Mirror averaging"): TAR at FPPF <= 0.1 on five sets of 16 synthetic rooms
  /// 0.771 / 0.677 / 0.741 / 0.774 / 0.604 -> 0.796 / 0.691 / 0.759 / 0.774 / 0.617, the UC3M lab and home
  /// the same (24 of 27, 19 of 22). It applies to models trained on a broad base, not to a model adapted
  /// to one room by rdsf-adapt (mirror_average_for): that model learned the room's negatives as the camera
  /// sees them (training mirrors positives only), and the mirror shows it views of the room it never
  /// learned; the adaptation benchmark's per-track models lost with it (docs/quality.md). The rounds such a
  /// model inherited from its base are averaged all the same (mirror_average_inherited).
  bool mirror_average = true;
  /// Whether `model`'s scores are mirror-averaged: mirror_average, unless the model was adapted to a room
  /// (TrainingRecord::adapted_to_a_room).
  bool mirror_average_for(const BoostedModel& model) const;
  /// With mirror_average, a model adapted to a room scores the rounds it continued (its base's: the training
  /// record's init_weak_classifiers) mirror-averaged and its own on the crop alone:
  ///   H = (H_inherited(crop) + H_inherited(mirror)) / 2 + H_own(crop)
  /// so that its base's part is read as the base is, and the room's corrections see the room as the camera
  /// does. false: the adapted model on the crop alone (before 2026-12-07). Measured by a rule written first
  /// (docs/adapting-to-your-room.md, "Scoring an adapted model"): on two fresh renderings (20 rooms) 677
  /// people against 674, 5 of the shipped model's people lost against 10, the UC3M lab 12 of 12 against 11
  /// in every run. A model adapted without this record (none inherited) is scored on the crop alone.
  bool mirror_average_inherited = true;
  /// The weak classifiers of `model` scored mirror-averaged when mirror_average_for(model) is false: its
  /// inherited ones with mirror_average_inherited, else 0.
  std::size_t inherited_mirror_rounds_for(const BoostedModel& model) const;
  /// Of a whole object and a piece cut out of it that both score as people, only the higher-scoring one
  /// is a detection (duplicate_candidates.hpp). Off: both are (which counts one person twice).
  bool suppress_duplicates = true;
  /// No person is taller than this (cm) at their own depth: a candidate whose strict box's height at the
  /// median of its depth crop's readings is more (object_height.hpp) is dropped before it is scored (a door
  /// frame, a curtain, a far wall, a person joined with what stands above them). 250 is a 2 m person's
  /// raised hand. The strict box is clipped to the image, so people the image cuts are never too tall. 0:
  /// off (the thesis). A decision of the detector, as mirror_average is: mining, labelling and training
  /// keep every candidate (the pipeline sets CandidateParams::max_height_cm of its own analyser only).
  /// Measured with people/v3 at its operating point (docs/quality.md, "The height limit at detection"): TAR
  /// at FPPF <= 0.1 and MOTA held or rose on every synthetic set (0 to +0.005 and 0 to +0.010), the UC3M
  /// lab's false positives at P >= 0.27 1 -> 0 in 24 frames.
  double max_person_height_cm = 250.0;
  /// Cut every candidate's colour crop (analysis.candidates[i].colour_crop), as the analyser does for
  /// mining and labelling. Off (default): only the detections get one, when they are found (tracking reads
  /// their colour histograms); the other candidates' stay empty. The same pixels, histograms and people.
  bool colour_crops_of_all = false;
};

/// The table of the PipelineParams a user sets (core/parameter_table.hpp): --threshold, --mirror-average and
/// --max-height (whose thesis values, off, --thesis applies) and --suppress-duplicates. score_threshold
/// (optional, no default) is cli::add_decision_options' own option.
const ParameterTable<PipelineParams>& decision_parameters();

struct PipelineFrame {
  FrameAnalysis analysis;                 ///< layers, candidates (features only with full_feature_vector)
  cv::Mat1f model_features;               ///< per candidate the features the model reads (ModelScorer order)
  std::vector<double> scores;             ///< H(x) per candidate (empty without a model)
  std::vector<double> probabilities;      ///< P(person) per candidate (empty without a model)
  std::vector<char> duplicate;            ///< per candidate: 1 when a duplicate, never a detection (with a model)
  std::vector<ColourHistogram> histograms;///< per candidate (empty histograms without colour)
  std::vector<int> person;                ///< per candidate: tracked person id, 0 when not a detection
  StageTimes times;
};

class PeoplePipeline {
 public:
  /// `model` may be null (candidates only); it must outlive the pipeline. Throws Error when the model's
  /// feature spec differs from the detector's (naming both).
  PeoplePipeline(PipelineParams params, const BoostedModel* model);

  /// analyse(frame) then track(frame, result): the whole system for the next frame.
  PipelineFrame process(const DepthFrame& frame);

  /// Everything before tracking: candidates, the features the model reads, H(x), P(person) and the
  /// detections' colour histograms (their time counts as tracking_ms). Const and thread-safe: frames may be
  /// analysed on several threads at once (parallel_pipeline.hpp). Throws Error when the depth image is
  /// empty or its size is not the frame's camera model's.
  PipelineFrame analyse(const DepthFrame& frame) const;
  /// Tracking: matches the detections of an analysed frame and fills `analysed.person`. Call with frames in
  /// order (the tracker's state), from one thread at a time.
  void track(const DepthFrame& frame, PipelineFrame& analysed);

  const Tracker& tracker() const { return tracker_; }
  const PipelineParams& params() const { return params_; }

 private:
  PipelineParams params_;
  const BoostedModel* model_;
  std::optional<ModelScorer> scorer_;
  std::optional<MirrorScoring> mirror_;  ///< how the crop scores become the candidates' (mirror_scoring.hpp)
  FrameAnalyser analyser_;
  Tracker tracker_;
};

}  // namespace rdsf
