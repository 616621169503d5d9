// The operating point rdsf-train --operating-tar chooses (operating_point.hpp).
#include "rdsf/classifier/operating_point.hpp"

#include <cstdio>

#include "rdsf/core/error.hpp"

namespace rdsf {

std::optional<OperatingPoint> choose_operating_point(const std::vector<double>& scores, const std::vector<int>& labels,
                                                     const ScoreCalibration& calibration, double target_tar) {
  if (scores.size() != labels.size()) throw Error("operating point: scores and labels differ in number");
  if (!(target_tar > 0.0 && target_tar <= 1.0)) throw Error("operating-tar must be in (0, 1]");
  std::size_t positives = 0, negatives = 0;
  for (const int label : labels) (label == 1 ? positives : negatives) += 1;
  if (positives == 0 || negatives == 0) return std::nullopt;
  for (int percent = 99; percent >= 1; --percent) {
    const double p = percent / 100.0;
    const double h = calibration.score_at(p);
    std::size_t tp = 0, fp = 0;
    for (std::size_t k = 0; k < scores.size(); ++k) {
      if (scores[k] >= h) (labels[k] == 1 ? tp : fp) += 1;
    }
    const double tar = static_cast<double>(tp) / static_cast<double>(positives);
    if (tar < target_tar) continue;
    const double far = static_cast<double>(fp) / static_cast<double>(negatives);
    char rule[160];
    std::snprintf(rule, sizeof rule,
                  "the highest P on a 0.01 grid with validation TAR >= %.3g (TAR %.3f, FAR %.4f there)", target_tar,
                  tar, far);
    return OperatingPoint{p, rule};
  }
  return std::nullopt;
}

}  // namespace rdsf
