#pragma once
// A model's operating point: the P(person) at which its user takes a candidate as a person, when the model
// states one (model file `operating_point`, format 3, optional). rdsf-detect, rdsf-adapt's presence guard
// and the ROS node read a model at its operating point unless the user gives --threshold; a model that
// states none (every model before people/v3) is read at P >= 0.5 (kDefaultOperatingProbability).
//
// Why a model states it: P(person) is calibrated on the model's own validation samples, so it says how
// likely a person is among candidates like those. Two models trained on different renderings put the same
// real person at different P: people/v3's validation people are harder to tell from clutter than v2's (its
// clutter has no rendered holes), so it gives the same real person a lower P and at 0.5 finds fewer.
//
// choose_operating_point (rdsf-train --operating-tar T): the highest P on the grid 0.01, 0.02, ..., 0.99
// at which at least a share T of the validation positives score P >= it (their pooled out-of-fold scores,
// the calibration the model carries); none when even P >= 0.01 keeps fewer. The choice reads the
// validation samples only, never frames of a real room.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "rdsf/classifier/platt_calibration.hpp"
#include "rdsf/classifier/training_record.hpp"

namespace rdsf {

inline constexpr double kDefaultOperatingProbability = 0.5;

struct OperatingPoint {
  double probability = kDefaultOperatingProbability;  ///< 0 < P < 1
  std::string rule;  ///< how it was chosen, with the validation TAR and FAR there
  /// The validation FAR at the point when it was chosen in this run (choose_operating_point); a model file
  /// keeps it in `rule`'s text only, so a loaded point has NaN.
  double validation_far = std::numeric_limits<double>::quiet_NaN();
};

/// Above this validation FAR at its operating point rdsf-train warns that the model tells people from clutter
/// poorly (the thesis's classifier: TAR 0.82 at FAR 0.05).
inline constexpr double kWeakOperatingFar = 0.05;

/// Validation TAR and FAR at P(person) >= `probability`: the shares of the positives and of the negatives
/// (`labels` 1/0) whose score reaches calibration.score_at(probability). What the model file's
/// validation.by_probability holds at each level, and what choose_operating_point reads at each grid point.
ProbabilityPoint rates_at_probability(const std::vector<double>& scores, const std::vector<int>& labels,
                                      const ScoreCalibration& calibration, double probability);

/// The point rdsf-train --operating-tar `target_tar` (0 < T <= 1) chooses; `labels` 1/0 beside `scores`.
std::optional<OperatingPoint> choose_operating_point(const std::vector<double>& scores, const std::vector<int>& labels,
                                                     const ScoreCalibration& calibration, double target_tar);

}  // namespace rdsf
