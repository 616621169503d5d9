#pragma once
// Native Real AdaBoost with look-up-table weak classifiers (Schapire and Singer's domain partitioning).
// Each round, for every feature in parallel, the weights of the positive and negative samples are summed
// per bin (W+_j, W-_j); the feature with the smallest Z = 2 sum_j sqrt(W+_j W-_j) is chosen, its bin
// responses are h_j = 0.5 ln((W+_j + eps) / (W-_j + eps)), and the weights become w_i exp(-y_i h(x_i)),
// normalised to sum 1 (y = +1 person, -1 not). Deterministic: no randomness, ties go to the lower feature
// index, and every feature's sums are taken in sample order whatever the thread count.
#include <cstddef>
#include <vector>

#include "classifier/binned_matrix.hpp"
#include "classifier/weak_classifier.hpp"

namespace rdsf {

struct RealAdaBoostParams {
  /// eps in the responses; 0 means 1 / (number of training samples).
  double smoothing = 0.0;
  /// Weight trimming: each round the lightest samples holding this fraction of the total weight are left
  /// out of the histograms (they are still reweighted and can come back). 0 = off; 0.05 is OpenCV's
  /// weight_trim_rate 0.95.
  double weight_trim = 0.0;
  /// Threads for the per-feature histograms; 0 = all cores.
  int threads = 0;
};

struct RealAdaBoostRound {
  int round = 0;              ///< 1-based
  int feature = 0;            ///< chosen feature
  double z = 0.0;             ///< its normalisation factor Z (smaller is better; 1 = useless)
  double train_error = 0.0;   ///< training error of the sign of the sum so far
  std::size_t samples_used = 0;  ///< samples in the histograms (fewer than all when trimming)
};

/// `indices` (all of 0..labels.size()-1 when empty) reordered positives first, each class in its given
/// order: the sample order with which RealAdaBoost takes its faster path (build the BinnedMatrix with it).
std::vector<std::size_t> positives_first_order(const std::vector<int>& labels,
                                               const std::vector<std::size_t>& indices = {});

class RealAdaBoost {
 public:
  /// `labels` (1 person, 0 not) in the sample order of `data`, which must outlive this object.
  RealAdaBoost(const BinnedMatrix& data, std::vector<int> labels, RealAdaBoostParams params = {});

  /// Adds one weak classifier and returns what was chosen.
  RealAdaBoostRound next_round();

  const std::vector<WeakClassifier>& weak_classifiers() const { return weak_; }
  /// Current strong-classifier score of every training sample.
  const std::vector<double>& train_scores() const { return scores_; }

 private:
  std::vector<std::size_t> trimmed_samples() const;

  const BinnedMatrix& data_;
  std::vector<int> labels_;
  RealAdaBoostParams params_;
  double eps_ = 0.0;
  bool positives_first_ = false;  ///< labels are 1...1 0...0: the faster four-feature histograms apply
  std::size_t positives_ = 0;
  int threads_ = 1;
  std::vector<double> weights_;
  std::vector<double> scores_;
  std::vector<WeakClassifier> weak_;
};

}  // namespace rdsf
