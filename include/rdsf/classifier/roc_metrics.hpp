#pragma once
// Figures of a scored, labelled set: the ROC curve (threshold sweep), its area, the true accept rate at a
// given false accept rate, and the error rate of the sign rule (score > 0 means person).
#include <vector>

namespace rdsf {

struct RocPoint {
  double far = 0.0;        ///< false accept rate: negatives scoring >= threshold / negatives
  double tar = 0.0;        ///< true accept rate: positives scoring >= threshold / positives
  double threshold = 0.0;  ///< score threshold
};

struct RocSummary {
  double auc = 0.0;            ///< area under the ROC curve (ties count one half)
  double tar_at_far_1 = 0.0;   ///< best TAR with FAR <= 1 %
  double tar_at_far_5 = 0.0;   ///< best TAR with FAR <= 5 %
  double error_rate = 0.0;     ///< fraction misclassified by score > 0
};

/// The full curve, one point per distinct score, from (0,0) (threshold above every score) to (1,1). `labels` are 1/0.
/// Throws Error when sizes differ or a class is missing.
std::vector<RocPoint> roc_curve(const std::vector<double>& scores, const std::vector<int>& labels);
/// Area under the curve (Mann-Whitney, ties one half).
double roc_auc(const std::vector<double>& scores, const std::vector<int>& labels);
/// Highest TAR among the curve's points with FAR <= max_far.
double tar_at_far(const std::vector<RocPoint>& curve, double max_far);
RocSummary summarise_roc(const std::vector<double>& scores, const std::vector<int>& labels);
/// The same from an already computed curve (error_rate needs the scores, so it is left 0 here).
RocSummary summarise_curve(const std::vector<RocPoint>& curve);
/// The curve's operating points at the FAR levels 0.1 %, 0.2 %, 0.5 %, 1 %, 2 %, 5 %, 10 %, 20 %, 50 %,
/// 100 % (for each level the point with the highest TAR at or below it; repeated points dropped): a short
/// curve for model files and reports that keeps the low-FAR end where detectors operate.
std::vector<RocPoint> roc_at_far_levels(const std::vector<RocPoint>& curve);

}  // namespace rdsf
