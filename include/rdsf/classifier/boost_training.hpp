#pragma once
// One training run from feature rows to a BoostedModel (not yet saved): validation split (by group when
// the rows' groups are given: recording and frame range, so near-identical crops of consecutive frames never
// sit on both sides), the chosen backend round by round, validation figures (AUC, TAR at FAR 1 % and 5 %)
// after every round, optional early stopping, Platt calibration of the scores on the validation samples,
// and a progress report per round. Takes feature matrices, not sample sets. train_boosted_model's steps
// (boost_training.cpp): check the rows, split them (separate sets, groups, or a stratified fraction), order
// the training side, boost with the backend while a RoundObserver keeps the figures and decides early
// stopping (an enum, not a message), then finish the model (kept rounds, record, calibration).
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/classifier/bin_scheme.hpp"
#include "rdsf/classifier/boost_backend.hpp"
#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/classifier/real_adaboost.hpp"
#include "rdsf/core/parameter_table.hpp"
#include "rdsf/classifier/row_shards.hpp"
#include "rdsf/features/feature_spec.hpp"

namespace rdsf {

/// The native backend's settings (smoothing, weight_trim, threads, depth, learning_rate,
/// histogram_subtraction) are RealAdaBoostSettings' (real_adaboost.hpp), with other defaults here; the
/// opencv backend reads weight_trim (and trains stumps whatever depth says). histogram_subtraction is
/// recorded in the model file only when on (off keeps the models the same bits).
struct BoostTrainingParams : RealAdaBoostSettings {
  /// Depth 2 and learning rate 0.5: chosen by the quality report (docs/quality.md); --thesis gives 1 and 1.
  BoostTrainingParams() {
    depth = 2;
    learning_rate = 0.5;
  }
  BoostBackend backend = BoostBackend::native;  ///< native (Real AdaBoost, LUT) or opencv (cv::ml::Boost REAL stumps)
  int rounds = 100;                 ///< boosting rounds (weak classifiers)
  BinScheme bins;                   ///< native: 64 equal bins over [0, 1]
  double validation_fraction = 0.2; ///< held out per class when no separate validation rows are given
  std::uint64_t seed = 1;           ///< validation split
  int report_every = 10;            ///< rounds between the figures kept in the model file (last always kept)
  int early_stopping = 0;           ///< stop after this many rounds without a better validation AUC, keep the best; 0 = off
  std::string calibration = "platt";  ///< "platt" (fitted on the validation samples) or "none" (P = sigmoid(2 H))
  /// K-fold validation by group (2-20; 0 = off): K models each trained without one fold of whole groups
  /// and scored on it; their pooled out-of-fold scores give every validation figure and the calibration
  /// of the final model, trained on all rows (the quality report measured it: real TAR at FPPF <= 0.1
  /// 0.63 -> 0.80 at tree2's size, docs/quality.md). Used when the rows' groups are given, no separate
  /// validation rows are, and early stopping is off (it needs one held-out split); else validation_fraction.
  int folds = 5;
  /// The model's operating point (operating_point.hpp): the highest P(person) at which at least this share
  /// of the validation positives are accepted. 0 (default): none stated, the model is read at P >= 0.5.
  double operating_tar = 0.0;
  FeatureSpec feature_spec;         ///< the features the rows hold and the model reads (the thesis's by default)
  /// When the rows hold only some of the spec's features (a pool, e.g. of the 120,786 rdsf-rect pairs): the
  /// feature of each column, distinct. Empty: every feature, column c = feature c. The model and the
  /// figures name features, not columns. Native backend only.
  std::vector<int> feature_columns;
  /// Continued training (`rdsf-train --init MODEL`): the weak classifiers of a model of the same spec and
  /// bins. Every training and validation score starts at their sum F0 (so the first new round sees the
  /// weights exp(-y F0) that model left), the new rounds follow, and the model kept is those weak
  /// classifiers first, then the new ones; its validation figures and calibration are the whole model's.
  /// Native backend, every feature in the rows (no pool). Empty: training from nothing.
  std::vector<WeakClassifier> init;
};

/// What is known of the rows beyond features and labels.
struct TrainingRowInfo {
  /// Group id per row (recording and frame range): the validation split holds out whole groups. Empty:
  /// every row is its own group (only right when rows are independent, e.g. generated data).
  std::vector<std::size_t> groups;
  /// Per row: true for augmented copies, which are only ever trained on (dropped with their group when it
  /// is held out). Empty: none.
  std::vector<bool> augmented;
  /// Data-parallel training (issue 37, row_shards.hpp): `rows` (and the separate validation rows) hold only
  /// this rank's share, in the rows' order; `owners` (`validation_owners`) says which rank holds each row.
  /// Labels, groups and augmentation marks are of every row, so every rank splits, folds and orders the
  /// rows alike; scores of held-out rows are gathered, the histograms summed (real_adaboost.hpp). Native
  /// backend only. Default: one process, every row here.
  RowOwners owners, validation_owners;
};

struct TrainingProgress {
  int round = 0, rounds = 0;
  int fold = 0, folds = 0;  ///< with group folds: model fold of folds (folds + 1 = the final model), else 0
  int feature = 0;
  double train_error = 0.0;
  std::optional<double> validation_error, validation_auc;
  double round_s = 0.0;    ///< time of this round
  double elapsed_s = 0.0;  ///< since the start of boosting (data preparation included)
  double left_s = 0.0;     ///< estimate for the remaining rounds
};

using TrainingProgressFn = std::function<void(const TrainingProgress&)>;

/// The table of BoostTrainingParams (boost_training_parameters.cpp): rdsf-train's boosting options, the
/// keys of recipes, the --thesis values (depth 1, learning rate 1) and each row's check.
const ParameterTable<BoostTrainingParams>& boost_training_parameters();

/// Throws Error on bad parameters, naming the parameter: every row of boost_training_parameters() checked
/// ("rounds must be at least 1"), then what rows cannot check alone (bin range, feature spec, --init, pool).
void validate_training_params(const BoostTrainingParams& params);

/// Trains on `rows` (one sample per row) with `labels` (1/0). Validation uses `validation_rows` /
/// `validation_labels` when given, else a stratified seeded held-out fraction of `rows`. The model's
/// training record has backend, parameters, counts, validation and why it stopped; recipe and sample
/// sets are the caller's to add.
BoostedModel train_boosted_model(const cv::Mat1f& rows, const std::vector<int>& labels,
                                 const BoostTrainingParams& params, const TrainingProgressFn& progress = {},
                                 const cv::Mat1f* validation_rows = nullptr,
                                 const std::vector<int>* validation_labels = nullptr,
                                 const TrainingRowInfo& info = {});

/// The probabilities at which the model file keeps validation TAR and FAR: 0.05, 0.10, ..., 0.95.
std::vector<double> probability_levels();

/// params.folds-fold validation by group (what train_boosted_model does when folds >= 2 and no separate
/// validation rows are given). Throws Error when there are fewer groups than folds or a fold lacks a class.
BoostedModel train_with_group_folds(const cv::Mat1f& rows, const std::vector<int>& labels,
                                    const BoostTrainingParams& params, const TrainingProgressFn& progress,
                                    const TrainingRowInfo& info);

/// Fills `figures` (summary, ROC points, by_probability) from validation scores, with params.calibration
/// "platt" fits the model's calibration on them, and with params.operating_tar > 0 sets the model's
/// operating point (choose_operating_point, operating_point.hpp).
void record_validation(BoostedModel& model, ValidationFigures& figures, const std::vector<double>& scores,
                       const std::vector<int>& labels, const BoostTrainingParams& params, const std::string& source);

}  // namespace rdsf
