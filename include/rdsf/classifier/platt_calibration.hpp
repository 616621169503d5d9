#pragma once
// Calibrated probabilities from boosting scores (Platt scaling).
//
// Real AdaBoost's H(x) estimates half the log-odds, P(person | x) = 1 / (1 + exp(-2 H(x))), but only on the
// training distribution: on new data a boosted model is over-confident. Platt scaling fits
//   P(person | H) = 1 / (1 + exp(-(a H + b)))
// by maximum likelihood on scores of samples the model was not trained on (the validation groups), with
// Platt's smoothed targets t+ = (N+ + 1) / (N+ + 2) and t- = 1 / (N- + 2) so that a perfectly separated
// validation set still gives finite a and b. Solved by Newton's method with a backtracking line search
// (the formulation of Lin, Lin and Weng's note on Platt's method), deterministic.
//
// The probabilities hold for the class balance of the samples the calibration was fitted on (for
// candidates of a labelled recording, that is the recording's own mix of people and other candidates).
#include <cstddef>
#include <string>
#include <vector>

namespace rdsf {

struct ScoreCalibration {
  std::string method = "none";  ///< "platt" (fitted) or "none" (P = 1 / (1 + exp(-2 H)))
  double a = 2.0, b = 0.0;      ///< P = 1 / (1 + exp(-(a H + b)))
  std::size_t positives = 0, negatives = 0;  ///< samples it was fitted on
  std::string source;           ///< what they were ("validation groups", ...)

  double probability(double score) const;
  /// The score whose probability is p (0 < p < 1): (logit(p) - b) / a.
  double score_at(double probability) const;
};

/// Fits a and b to `scores` with `labels` (1/0). Throws Error when a class is missing or the sizes differ.
ScoreCalibration fit_platt(const std::vector<double>& scores, const std::vector<int>& labels);

}  // namespace rdsf
