#pragma once
// rdsf-adapt's held-out check step (--holdout-check; the rule and its figures: pipeline/holdout_check.hpp):
// the room's frames split in time, a trial model trained on the samples of the earlier half (copied into sets
// of their own under the check's folder), the trial and the model as given scoring the later half's labelled
// candidates, and with switches taken the model as given without them its own candidates. The state says which
// becomes the room's model: "check" = "trial kept" (the room's model is trained on everything), "base kept" (the
// model as given, stating the switches taken), "as given kept" (the model as given, the switches dropped) or
// "none" (the room's frames have no names in order: no check); "check.figures" and "check_train_seconds" say why.
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "adapt/adapt_state.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/classifier/boosted_model.hpp"

namespace rdsf {

struct HoldoutInputs {
  std::string source;                  ///< the room's recording (its frame names, in order)
  std::vector<std::string> room_sets;  ///< the room's answers and the switches' trials: every sample from its frames
  std::string negatives;               ///< the room's mined negatives, or empty
  bool negatives_from_room = false;    ///< they were mined from the room's own frames (no --empty): split too
  /// When the trials took switches: the analyser options of the model as given, without them (a third figure:
  /// pipeline/holdout_check.hpp); else unset.
  std::optional<AnalyserParams> as_given;
  std::string dir;                     ///< the check's folder (emptied first: a killed check starts again)
  std::string log;                     ///< the step's log
};

/// Trains the trial on (room sets, negatives) as the room's model is trained: (path written, seconds).
using TrialTraining =
    std::function<std::pair<std::string, std::string>(const std::vector<std::string>&, const std::string&)>;

void run_holdout_check(const HoldoutInputs& in, const BoostedModel& model, AdaptState& state,
                       const TrialTraining& train);

}  // namespace rdsf
