// The operating point rdsf-train --operating-tar chooses (operating_point.hpp).
#include "rdsf/classifier/operating_point.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdio>

#include "rdsf/core/error.hpp"

namespace rdsf {

ProbabilityPoint rates_at_probability(const std::vector<double>& scores, const std::vector<int>& labels,
                                      const ScoreCalibration& calibration, double probability) {
  const double h = calibration.score_at(probability);
  std::size_t positives = 0, tp = 0, fp = 0;
  for (std::size_t k = 0; k < scores.size(); ++k) {
    positives += labels[k] == 1 ? 1 : 0;
    if (scores[k] >= h) (labels[k] == 1 ? tp : fp) += 1;
  }
  const auto negatives = static_cast<double>(labels.size() - positives);
  return {probability, static_cast<double>(tp) / static_cast<double>(positives), static_cast<double>(fp) / negatives};
}

std::optional<OperatingPoint> choose_operating_point(const std::vector<double>& scores, const std::vector<int>& labels,
                                                     const ScoreCalibration& calibration, double target_tar) {
  if (scores.size() != labels.size()) throw Error("operating point: scores and labels differ in number");
  if (!(target_tar > 0.0 && target_tar <= 1.0)) throw Error("operating-tar must be in (0, 1]");
  const auto positives = std::count(labels.begin(), labels.end(), 1);
  if (positives == 0 || positives == static_cast<std::ptrdiff_t>(labels.size())) return std::nullopt;
  for (int percent = 99; percent >= 1; --percent) {
    const ProbabilityPoint at = rates_at_probability(scores, labels, calibration, percent / 100.0);
    if (at.tar < target_tar) continue;
    char rule[160];
    std::snprintf(rule, sizeof rule,
                  "the highest P on a 0.01 grid with validation TAR >= %.3g (TAR %.3f, FAR %.4f there)", target_tar,
                  at.tar, at.far);
    return OperatingPoint{at.probability, rule, at.far};
  }
  return std::nullopt;
}

}  // namespace rdsf
