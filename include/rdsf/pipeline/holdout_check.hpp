#pragma once
// rdsf-adapt's held-out check (--holdout-check): is a room's model better than the model it continues, on
// frames it was not trained on? The room's adaptation frames are split in time: a trial model is trained on
// the samples of the earlier half, and the trial and the base model score the labelled candidates of the later
// half (the person's answers, the labels propagated along their tracks, the model's sure answers, the room's
// negatives there) as the detector scores them (MirrorScoring). Each finds
//   people_found_at_fppf = #{person scores > s_(a+1)},  a = floor(max_fppf x frames + 1e-9),
// s_(a+1) the (a+1)-th highest score of the other candidates (every person when there are at most a others):
// the most people a threshold finds while accepting at most a of the others, i.e. TAR x people at FAR <= a /
// others of the labelled candidates' ROC curve (classifier/roc_metrics.hpp; candidates nobody labelled count
// for neither).
// The trial replaces the base only when it finds at least as many (HoldoutFigures::trial_kept).
// When the room's trials took candidate switches, the base scores the switched candidates: a third figure is then
// the model as given with its own options, without the switches (its own candidates of the later half scored as
// the detector scores them; each labelled place takes the highest score of those whose strict box overlaps it at
// IoU >= 0.5, a labelled person none overlaps is missed, a candidate that overlaps no labelled place counts for
// neither), and it wins
// only when it finds more people than both others (HoldoutFigures::as_given_kept): the switches are then dropped
// with the training.
#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"

namespace rdsf {

/// The later half of a recording's frame names (given in the recording's order): the last n - n / 2.
std::vector<std::string> later_half(const std::vector<std::string>& names_in_order);

/// The most people found (person scores above the threshold) at FPPF <= max_fppf over `frames` frames, the
/// other candidates' scores deciding the threshold (header comment). Throws Error when frames < 1.
std::size_t people_found_at_fppf(const std::vector<double>& person_scores, const std::vector<double>& other_scores,
                                 std::size_t frames, double max_fppf);

/// Each window-sized masked depth crop's score as the detector gives it with `params` (H(x) of the crop, or
/// mirror-averaged as MirrorScoring says for `model`).
std::vector<double> detector_scores(const BoostedModel& model, const PipelineParams& params,
                                    const std::vector<cv::Mat1w>& crops);

/// The model as given, made the room's model when the check keeps it: the same weak classifiers, calibration
/// and operating point, stating `detection_options` (unless empty), recording `provenance` (rdsf-adapt's
/// adapted_room, ...) and every weak classifier as inherited (init_weak_classifiers), so that a detector
/// mirror-averages all of it, as it scores the model as given: detector_scores() are the same bit for bit.
BoostedModel base_as_room_model(BoostedModel base, const RecordedParameters& detection_options,
                                const RecordedParameters& provenance);

struct HoldoutFigures {
  std::size_t frames = 0;         ///< the later half's frames
  std::size_t people = 0;         ///< labelled person candidates there
  std::size_t others = 0;         ///< labelled other candidates there
  std::size_t base_found = 0;     ///< people_found_at_fppf of the base model
  std::size_t trial_found = 0;    ///< of the trial model
  /// With switches taken: people_found_at_fppf of the model as given without them (header comment).
  std::optional<std::size_t> as_given_found;
  /// The model as given, without the switches, finds more than the base stating them and the trial.
  bool as_given_kept() const { return as_given_found && *as_given_found > std::max(base_found, trial_found); }
  /// The trial (the room's model) replaces the base: it finds at least as many (both 0 when nobody is labelled),
  /// and the model as given without the switches does not win.
  bool trial_kept() const { return !as_given_kept() && trial_found >= base_found; }
};

}  // namespace rdsf
