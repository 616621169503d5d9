#pragma once
// One training run from feature rows to a BoostedModel (not yet saved): validation split, the chosen
// backend round by round, validation figures (AUC, TAR at FAR 1 % and 5 %) after every round, optional
// early stopping, and a progress report per round. Takes feature matrices, not sample sets.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "classifier/bin_scheme.hpp"
#include "classifier/boosted_model.hpp"
#include "features/feature_spec.hpp"

namespace rdsf {

struct BoostTrainingParams {
  std::string backend = "native";   ///< "native" (Real AdaBoost, LUT) or "opencv" (cv::ml::Boost REAL stumps)
  int rounds = 100;                 ///< boosting rounds (weak classifiers)
  BinScheme bins;                   ///< native: 64 equal bins over [0, 1]
  double smoothing = 0.0;           ///< native: eps of the responses; 0 = 1 / training samples
  double weight_trim = 0.0;         ///< fraction of the weight trimmed per round; 0 = off
  int threads = 0;                  ///< native: 0 = all cores (does not change the result)
  double validation_fraction = 0.2; ///< held out per class when no separate validation rows are given
  std::uint64_t seed = 1;           ///< validation split
  int report_every = 10;            ///< rounds between the figures kept in the model file (last always kept)
  int early_stopping = 0;           ///< stop after this many rounds without a better validation AUC, keep the best; 0 = off
  FeatureSpec feature_spec;         ///< the features the rows hold and the model reads (the thesis's by default)
  /// When the rows hold only some of the spec's features (a pool, e.g. of the 120,786 rdsf-rect pairs): the
  /// feature of each column, distinct. Empty: every feature, column c = feature c. The model and the
  /// figures name features, not columns. Native backend only.
  std::vector<int> feature_columns;
};

struct TrainingProgress {
  int round = 0, rounds = 0;
  int feature = 0;
  double train_error = 0.0;
  std::optional<double> validation_error, validation_auc;
  double round_s = 0.0;    ///< time of this round
  double elapsed_s = 0.0;  ///< since the start of boosting (data preparation included)
  double left_s = 0.0;     ///< estimate for the remaining rounds
};

using TrainingProgressFn = std::function<void(const TrainingProgress&)>;

/// Throws Error on bad parameters (unknown backend, rounds < 1, ...), naming the parameter.
void validate_training_params(const BoostTrainingParams& params);

/// Trains on `rows` (one sample per row) with `labels` (1/0). Validation uses `validation_rows` /
/// `validation_labels` when given, else a stratified seeded held-out fraction of `rows`. The model's
/// training record has backend, parameters, counts, validation and why it stopped; recipe and sample
/// sets are the caller's to add.
BoostedModel train_boosted_model(const cv::Mat1f& rows, const std::vector<int>& labels,
                                 const BoostTrainingParams& params, const TrainingProgressFn& progress = {},
                                 const cv::Mat1f* validation_rows = nullptr,
                                 const std::vector<int>* validation_labels = nullptr);

}  // namespace rdsf
