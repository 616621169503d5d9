#include "rdsf/classifier/boost_training.hpp"

#include <algorithm>
#include <map>
#include <chrono>
#include <cstdio>

#include "rdsf/classifier/binned_matrix.hpp"
#include "rdsf/classifier/dense_groups.hpp"
#include "rdsf/classifier/features_read.hpp"
#include "rdsf/classifier/opencv_boost.hpp"
#include "rdsf/classifier/platt_calibration.hpp"
#include "rdsf/classifier/seeded_sampling.hpp"
#include "rdsf/classifier/real_adaboost.hpp"
#include "rdsf/classifier/roc_metrics.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// Validation samples: rows of a matrix, by index.
struct ValidationView {
  const cv::Mat1f* rows = nullptr;
  const RowOwners* owners = nullptr;  // which rank holds each of `rows` (data-parallel training)
  std::vector<std::size_t> index;
  std::vector<int> labels;
  bool empty() const { return labels.empty(); }
  bool has_both_classes() const {
    return std::count(labels.begin(), labels.end(), 1) > 0 && std::count(labels.begin(), labels.end(), 0) > 0;
  }
};

// The model file's training.parameters: the table's record of every row (boost_training_parameters.cpp),
// then how many weak classifiers a continued model started from.
RecordedParameters parameter_record(const BoostTrainingParams& p) {
  RecordedParameters out = parameter_values(boost_training_parameters(), p);
  if (!p.init.empty()) out.emplace_back(kInitWeakClassifiersParameter, std::to_string(p.init.size()));
  return out;
}


// score(row) of the rows `index` lists (global indices), each computed by the rank holding it, in order on
// every rank; with one process simply in order.
template <typename Score>
std::vector<double> scores_of(const cv::Mat1f& rows, const std::vector<std::size_t>& index, const RowOwners& owners,
                              Score score) {
  std::vector<double> local;
  local.reserve(index.size());
  for (std::size_t i : index) {
    const long l = owners.local(i);
    if (l >= 0) local.push_back(score(rows[static_cast<int>(l)]));
  }
  return owners.whole(local, index);
}

// Column c of the rows -> feature of the spec (the pool's feature, or c itself).
struct ColumnFeatures {
  const std::vector<int>* columns = nullptr;
  int operator()(int column) const { return columns->empty() ? column : (*columns)[static_cast<std::size_t>(column)]; }
};

// Step 1: the rows, labels and row information agree with each other and with the feature spec.
void check_rows(const cv::Mat1f& rows, const std::vector<int>& labels, const BoostTrainingParams& params,
                const TrainingRowInfo& info) {
  const std::size_t held =
      info.owners.owner.empty()
          ? labels.size()
          : static_cast<std::size_t>(std::count_if(info.owners.local_of.begin(), info.owners.local_of.end(),
                                                   [](long l) { return l >= 0; }));
  if (!info.owners.owner.empty() && info.owners.owner.size() != labels.size()) {
    throw Error("training: owners of " + std::to_string(info.owners.owner.size()) + " rows for " +
                std::to_string(labels.size()) + " labels");
  }
  if (rows.rows != static_cast<int>(held)) {
    throw Error("training: " + std::to_string(rows.rows) + " rows for " + std::to_string(held) + " labels");
  }
  if (info.owners.distributed() && params.backend != BoostBackend::native) {
    throw Error("data-parallel training needs the native backend");
  }
  const std::vector<int>& columns = params.feature_columns;
  const int column_count = columns.empty() ? params.feature_spec.dimension() : static_cast<int>(columns.size());
  if (rows.cols != column_count) {
    throw Error("training: rows of " + std::to_string(rows.cols) + " features, the feature spec has " +
                std::to_string(column_count) + (columns.empty() ? "" : " in the pool"));
  }
  if ((!info.groups.empty() && info.groups.size() != labels.size()) ||
      (!info.augmented.empty() && info.augmented.size() != labels.size())) {
    throw Error("training: groups or augmentation marks do not match the rows");
  }
}

// Step 2: which rows train and which validate, and the text saying so.
struct TrainValidationSplit {
  std::vector<std::size_t> train_index;
  ValidationView validation;
  std::string source = "none";
};

TrainValidationSplit split_rows(const cv::Mat1f& rows, const std::vector<int>& labels, const BoostTrainingParams& params,
                                const cv::Mat1f* validation_rows, const std::vector<int>* validation_labels,
                                const TrainingRowInfo& info) {
  TrainValidationSplit out;
  ValidationView& validation = out.validation;
  if (validation_rows != nullptr && validation_labels != nullptr && !validation_labels->empty()) {
    const std::size_t here = info.validation_owners.owner.empty()
                                 ? validation_labels->size()
                                 : static_cast<std::size_t>(std::count_if(info.validation_owners.local_of.begin(),
                                                                          info.validation_owners.local_of.end(),
                                                                          [](long l) { return l >= 0; }));
    if (validation_rows->rows != static_cast<int>(here) || validation_rows->cols != rows.cols) {
      throw Error("training: validation rows and labels do not match");
    }
    for (std::size_t i = 0; i < labels.size(); ++i) out.train_index.push_back(i);
    validation.rows = validation_rows;
    validation.owners = &info.validation_owners;
    validation.labels = *validation_labels;
    for (std::size_t i = 0; i < validation.labels.size(); ++i) validation.index.push_back(i);
    out.source = "separate sets";
  } else if (!info.groups.empty() && params.validation_fraction > 0.0) {
    auto is_augmented = [&](std::size_t i) { return !info.augmented.empty() && info.augmented[i]; };
    std::vector<bool> counts;
    if (!info.augmented.empty()) {
      for (bool a : info.augmented) counts.push_back(!a);
    }
    const HoldOutSplit split = group_split(labels, info.groups, params.validation_fraction, params.seed, counts);
    out.train_index = split.train;
    validation.rows = &rows;
    validation.owners = &info.owners;
    std::vector<std::size_t> held_groups;
    for (std::size_t i : split.validation) {
      held_groups.push_back(info.groups[i]);
      if (is_augmented(i)) continue;  // copies of held-out samples are neither trained on nor validated
      validation.index.push_back(i);
      validation.labels.push_back(labels[i]);
    }
    out.source = "held-out groups: " + std::to_string(dense_groups(held_groups).count) + " of " +
                 std::to_string(dense_groups(info.groups).count) + " (recording and frame range), about " +
                 number_text(params.validation_fraction * 100.0) + "% per class (seed " + std::to_string(params.seed) +
                 ")";
  } else {
    const HoldOutSplit split = stratified_split(labels, params.validation_fraction, params.seed);
    out.train_index = split.train;
    validation.rows = &rows;
    validation.owners = &info.owners;
    validation.index = split.validation;
    for (std::size_t i : split.validation) validation.labels.push_back(labels[i]);
    if (!validation.index.empty()) {
      out.source = "held-out " + number_text(params.validation_fraction * 100.0) + "% per class (seed " +
                   std::to_string(params.seed) + "; samples, not groups)";
    }
  }
  return out;
}

// Step 3: the training rows in the native trainer's faster layout (positives first) and their labels.
struct TrainingSide {
  std::vector<std::size_t> index;
  std::vector<int> labels;
  std::size_t positives = 0;
};

TrainingSide training_side(const std::vector<int>& labels, const std::vector<std::size_t>& train_index) {
  TrainingSide side;
  side.index = positives_first_order(labels, train_index);
  side.labels.reserve(side.index.size());
  for (std::size_t i : side.index) side.labels.push_back(labels[i]);
  side.positives = static_cast<std::size_t>(std::count(side.labels.begin(), side.labels.end(), 1));
  if (side.positives == 0 || side.positives == side.labels.size()) {
    throw Error("training: both positive and negative training samples are needed (" + std::to_string(side.positives) +
                " positives, " + std::to_string(side.labels.size() - side.positives) + " negatives)");
  }
  return side;
}

// `weak` (naming the spec's features) with its features numbered as the rows' columns: the pool's position
// of each, when the rows hold a pool (every feature `weak` reads must be in it), else unchanged.
std::vector<WeakClassifier> on_row_columns(std::vector<WeakClassifier> weak, const BoostTrainingParams& params) {
  if (params.feature_columns.empty()) return weak;
  std::map<int, int> column_of;
  for (std::size_t c = 0; c < params.feature_columns.size(); ++c) column_of[params.feature_columns[c]] = static_cast<int>(c);
  renumber_features(weak, [&column_of](int feature) { return column_of.at(feature); });
  return weak;
}

// Continued training: the score F0 of params.init (H(x) of a model of those weak classifiers) on each of
// `rows`' rows in `index` (indices into `rows`); every feature it reads is in the rows (validate_training_params).
std::vector<double> init_scores(const cv::Mat1f& rows, const std::vector<std::size_t>& index, const BoostTrainingParams& params) {
  const BoostedModel init(params.feature_spec, params.bins, on_row_columns(params.init, params));
  std::vector<double> scores(index.size(), 0.0);
  for (std::size_t k = 0; k < index.size(); ++k) scores[k] = init.score(rows[static_cast<int>(index[k])]);
  return scores;
}

// Why boosting ended.
enum class Stop {
  all_rounds,      ///< every round of params.rounds
  early_stopping,  ///< params.early_stopping rounds without a better validation AUC
};

// Step 4: after each weak classifier, the validation figures, the progress report and the early-stopping
// decision.
class RoundObserver {
 public:
  RoundObserver(const BoostTrainingParams& params, const ValidationView& validation, bool validating,
                ColumnFeatures feature_of, const TrainingProgressFn& progress, Clock::time_point start)
      : params_(params), validation_(validation), validating_(validating), feature_of_(feature_of),
        progress_(progress), start_(start), scores_(validation.labels.size(), 0.0) {
    // The validation rows this rank holds (all of them with one process), as rows of validation.rows.
    for (std::size_t i : validation.index) {
      const long l = validation.owners == nullptr ? static_cast<long>(i) : validation.owners->local(i);
      if (l >= 0) local_rows_.push_back(static_cast<std::size_t>(l));
    }
    local_scores_.assign(local_rows_.size(), 0.0);
    if (!params.init.empty() && validation.rows != nullptr) local_scores_ = init_scores(*validation.rows, local_rows_, params);
  }

  /// Returns false to stop (early stopping).
  bool after_round(int round, const WeakClassifier& weak, double train_error, double round_s, double mean_round_s) {
    RoundFigures figures;
    figures.round = round;
    figures.feature = feature_of_(weak.feature);
    figures.train_error = train_error;
    TrainingProgress report;
    report.round = round;
    report.rounds = params_.rounds;
    report.feature = feature_of_(weak.feature);
    report.train_error = train_error;
    if (validating_) {
      for (std::size_t k = 0; k < local_rows_.size(); ++k) {
        local_scores_[k] += weak.respond_row((*validation_.rows)[static_cast<int>(local_rows_[k])], params_.bins);
      }
      scores_ = validation_.owners == nullptr ? local_scores_ : validation_.owners->whole(local_scores_, validation_.index);
      const RocSummary s = summarise_roc(scores_, validation_.labels);
      figures.roc = roc_at_far_levels(roc_curve(scores_, validation_.labels));
      figures.validation = s;
      report.validation_error = s.error_rate;
      report.validation_auc = s.auc;
      if (s.auc > best_auc_ + 1e-9) {
        best_auc_ = s.auc;
        best_round_ = round;
      }
    }
    rounds_.push_back(figures);
    report.round_s = round_s;
    report.elapsed_s = seconds_since(start_);
    report.left_s = mean_round_s * (params_.rounds - round);
    if (progress_) progress_(report);
    if (validating_ && params_.early_stopping > 0 && round - best_round_ >= params_.early_stopping) {
      stop_ = Stop::early_stopping;
      stop_round_ = round;
      return false;
    }
    return true;
  }

  Stop stop() const { return stop_; }
  int best_round() const { return best_round_; }
  const std::vector<RoundFigures>& rounds() const { return rounds_; }
  /// The model file's training.stopped.
  std::string stopped_text() const {
    if (stop_ == Stop::all_rounds) return "all " + std::to_string(params_.rounds) + " rounds";
    return "early stopping at round " + std::to_string(stop_round_) + ": no better validation AUC for " +
           std::to_string(params_.early_stopping) + " rounds; kept the best, round " + std::to_string(best_round_);
  }

 private:
  const BoostTrainingParams& params_;
  const ValidationView& validation_;
  bool validating_;
  ColumnFeatures feature_of_;
  const TrainingProgressFn& progress_;
  Clock::time_point start_;
  std::vector<double> scores_;  // validation scores so far
  std::vector<std::size_t> local_rows_;  // the validation rows held here, as rows of validation_.rows
  std::vector<double> local_scores_;     // their scores so far
  std::vector<RoundFigures> rounds_;
  double best_auc_ = -1.0;
  int best_round_ = 0;
  Stop stop_ = Stop::all_rounds;
  int stop_round_ = 0;
};

// Step 5: the backend's rounds.
struct Boosted {
  std::vector<WeakClassifier> weak;
  std::string opencv_yaml;       // OpenCV's own model, empty for native
  std::size_t opencv_trees = 0;  // trees in it
};

Boosted boost_native(const cv::Mat1f& rows, const TrainingSide& side, const BoostTrainingParams& params,
                     RoundObserver& observer, const RowOwners& owners) {
  // The training rows held here (all of them with one process), in the side's order.
  std::vector<std::size_t> local_index;
  std::vector<int> local_labels;
  for (std::size_t k = 0; k < side.index.size(); ++k) {
    const long l = owners.local(side.index[k]);
    if (l < 0) continue;
    local_index.push_back(static_cast<std::size_t>(l));
    local_labels.push_back(side.labels[k]);
  }
  const BinnedMatrix binned(rows, params.bins, local_index, params.threads);
  RealAdaBoostParams rp;
  static_cast<RealAdaBoostSettings&>(rp) = params;
  rp.shards = owners.distributed() ? owners.shards : nullptr;
  RealAdaBoost booster(binned, local_labels, rp);
  if (!params.init.empty()) booster.start_from_scores(init_scores(rows, local_index, params));
  const Clock::time_point boost_start = Clock::now();
  for (int round = 1; round <= params.rounds; ++round) {
    const Clock::time_point round_start = Clock::now();
    const RealAdaBoostRound r = booster.next_round();
    const double round_s = seconds_since(round_start);
    if (!observer.after_round(round, booster.weak_classifiers().back(), r.train_error, round_s,
                              seconds_since(boost_start) / round)) {
      break;
    }
  }
  Boosted out;
  out.weak = booster.weak_classifiers();
  return out;
}

Boosted boost_opencv(const cv::Mat1f& rows, const TrainingSide& side, const BoostTrainingParams& params,
                     RoundObserver& observer) {
  cv::Mat1f train_rows(static_cast<int>(side.index.size()), rows.cols);
  for (std::size_t k = 0; k < side.index.size(); ++k) {
    rows.row(static_cast<int>(side.index[k])).copyTo(train_rows.row(static_cast<int>(k)));
  }
  OpenCvBoostParams op;
  op.rounds = params.rounds;
  op.weight_trim = params.weight_trim;
  const Clock::time_point boost_start = Clock::now();
  OpenCvBoostResult result = train_opencv_boost(train_rows, side.labels, op);
  const double mean_round_s = seconds_since(boost_start) / std::max<std::size_t>(1, result.stumps.size());
  Boosted out;
  out.opencv_yaml = std::move(result.yaml);
  out.opencv_trees = result.stumps.size();
  // Per-round figures after the fact: OpenCV trains all rounds in one call.
  std::vector<double> train_scores(side.labels.size(), 0.0);
  int round = 0;
  for (const WeakClassifier& w : result.stumps) {
    ++round;
    std::size_t wrong = 0;
    for (std::size_t k = 0; k < train_scores.size(); ++k) {
      train_scores[k] += w.respond(train_rows(static_cast<int>(k), w.feature), params.bins);
      wrong += ((train_scores[k] > 0.0) != (side.labels[k] == 1)) ? 1 : 0;
    }
    out.weak.push_back(w);
    if (!observer.after_round(round, w, static_cast<double>(wrong) / static_cast<double>(train_scores.size()),
                              mean_round_s, 0.0)) {
      break;
    }
  }
  return out;
}

// Step 6: the model: the kept rounds, its training record, validation figures and calibration, the
// spec's feature numbers.
BoostedModel finish_model(Boosted boosted, const RoundObserver& observer, const BoostTrainingParams& params,
                          const TrainValidationSplit& split, const TrainingSide& side, ColumnFeatures feature_of) {
  std::vector<WeakClassifier>& weak = boosted.weak;
  if (observer.stop() == Stop::early_stopping && static_cast<std::size_t>(observer.best_round()) < weak.size()) {
    weak.resize(static_cast<std::size_t>(observer.best_round()));
  }
  if (!boosted.opencv_yaml.empty() && weak.size() != boosted.opencv_trees) {
    boosted.opencv_yaml.clear();  // the embedded model would no longer match the kept stumps
  }
  const ValidationView& validation = split.validation;
  TrainingRecord record;
  record.backend = params.backend.name();
  record.parameters = parameter_record(params);
  record.train_positives = side.positives;
  record.train_negatives = side.labels.size() - side.positives;
  record.validation.source = split.source;
  record.validation.positives =
      static_cast<std::size_t>(std::count(validation.labels.begin(), validation.labels.end(), 1));
  record.validation.negatives = validation.labels.size() - record.validation.positives;
  record.stopped = observer.stopped_text();
  // Figures kept in the file: every report_every rounds and the last kept round.
  for (const RoundFigures& f : observer.rounds()) {
    if (f.round > static_cast<int>(weak.size())) break;
    if (f.round % params.report_every == 0 || f.round == static_cast<int>(weak.size())) {
      record.validation.rounds.push_back(f);
    }
  }

  const std::vector<WeakClassifier> init = on_row_columns(params.init, params);
  weak.insert(weak.begin(), init.begin(), init.end());  // continued training: its model first, on the rows' columns
  BoostedModel model(params.feature_spec, params.bins, std::move(weak));
  if (validation.has_both_classes()) {
    const std::vector<double> final_scores =
        scores_of(*validation.rows, validation.index, validation.owners == nullptr ? RowOwners{} : *validation.owners,
                  [&model](const float* row) { return model.score(row); });
    record_validation(model, record.validation, final_scores, validation.labels, params, split.source);
  }
  if (!params.feature_columns.empty()) {  // columns of the pool -> features of the spec
    std::vector<WeakClassifier> renumbered = model.weak_classifiers();
    renumber_features(renumbered, feature_of);
    const ScoreCalibration calibration = model.calibration();
    const std::optional<OperatingPoint> operating_point = model.operating_point();
    model = BoostedModel(params.feature_spec, params.bins, std::move(renumbered));
    model.set_calibration(calibration);
    model.set_operating_point(operating_point);
  }
  model.training() = record;
  model.set_opencv_model_yaml(std::move(boosted.opencv_yaml));
  return model;
}

}  // namespace

void record_validation(BoostedModel& model, ValidationFigures& figures, const std::vector<double>& scores,
                       const std::vector<int>& labels, const BoostTrainingParams& params, const std::string& source) {
  figures.summary = summarise_roc(scores, labels);
  figures.roc = roc_at_far_levels(roc_curve(scores, labels));
  if (params.calibration == "platt") {
    ScoreCalibration c = fit_platt(scores, labels);
    c.source = source;
    model.set_calibration(c);
  }
  figures.by_probability.clear();
  for (double p : probability_levels()) {
    figures.by_probability.push_back(rates_at_probability(scores, labels, model.calibration(), p));
  }
  if (params.operating_tar > 0.0) {
    model.set_operating_point(choose_operating_point(scores, labels, model.calibration(), params.operating_tar));
  }
}

void validate_training_params(const BoostTrainingParams& p) {
  BoostTrainingParams checked = p;
  for (const Parameter<BoostTrainingParams>& row : boost_training_parameters()) row.set(checked, row.get(p));
  p.bins.validate();
  p.feature_spec.validate();
  if (!p.init.empty()) {
    if (p.backend != BoostBackend::native) throw Error("continued training (--init) needs the native backend");
    if (!p.feature_columns.empty()) {
      for (const int f : features_read(p.init)) {
        if (std::find(p.feature_columns.begin(), p.feature_columns.end(), f) == p.feature_columns.end()) {
          throw Error("continued training (--init): the model reads feature " + std::to_string(f) +
                      ", which the rows' feature pool does not hold");
        }
      }
    }
    for (const WeakClassifier& w : p.init) {
      if (w.feature < 0 || w.feature >= p.feature_spec.dimension()) {
        throw Error("continued training (--init): the model reads feature " + std::to_string(w.feature) +
                    ", outside " + p.feature_spec.name() + "'s " + std::to_string(p.feature_spec.dimension()));
      }
    }
  }
  if (!p.feature_columns.empty()) {
    if (p.backend != BoostBackend::native) throw Error("a feature pool needs the native backend");
    std::vector<int> sorted = p.feature_columns;
    std::sort(sorted.begin(), sorted.end());
    if (sorted.front() < 0 || sorted.back() >= p.feature_spec.dimension() ||
        std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      throw Error("feature pool: columns must be distinct features of " + p.feature_spec.name());
    }
  }
}

std::vector<double> probability_levels() {
  std::vector<double> out;
  for (int k = 1; k <= 19; ++k) out.push_back(k * 0.05);
  return out;
}

BoostedModel train_boosted_model(const cv::Mat1f& rows, const std::vector<int>& labels,
                                 const BoostTrainingParams& params, const TrainingProgressFn& progress,
                                 const cv::Mat1f* validation_rows, const std::vector<int>* validation_labels,
                                 const TrainingRowInfo& info) {
  validate_training_params(params);
  if (params.folds >= 2 && params.early_stopping == 0 && !info.groups.empty() &&
      (validation_labels == nullptr || validation_labels->empty())) {
    return train_with_group_folds(rows, labels, params, progress, info);
  }
  const Clock::time_point start = Clock::now();
  check_rows(rows, labels, params, info);
  const TrainValidationSplit split = split_rows(rows, labels, params, validation_rows, validation_labels, info);
  const bool validating = split.validation.has_both_classes();
  if (params.early_stopping > 0 && !validating) {
    throw Error("early stopping needs validation samples of both classes (a validation fraction or set)");
  }
  const TrainingSide side = training_side(labels, split.train_index);
  const ColumnFeatures feature_of{&params.feature_columns};
  RoundObserver observer(params, split.validation, validating, feature_of, progress, start);
  Boosted boosted = params.backend == BoostBackend::native ? boost_native(rows, side, params, observer, info.owners)
                                                           : boost_opencv(rows, side, params, observer);
  return finish_model(std::move(boosted), observer, params, split, side, feature_of);
}

namespace {

/// The folds' held-out rows, pooled in fold order: their labels, their final scores and their scores after
/// each new round (of every rank's rows, in order).
struct PooledOutOfFold {
  std::vector<double> scores;
  std::vector<int> labels;
  std::vector<std::vector<double>> per_round;
};

/// Trains `inner` on the rows `train_rows_index` (of every rank; the ones held here are taken from `rows`).
BoostedModel train_fold(const cv::Mat1f& rows, const std::vector<int>& labels, const TrainingRowInfo& info,
                        const std::vector<int>& train_rows_index, const BoostTrainingParams& inner, std::size_t f,
                        std::size_t folds, const TrainingProgressFn& fold_progress) {
  // The fold's rows held here (all of them with one process).
  TrainingRowInfo fold_info;
  fold_info.owners = info.owners.subset(train_rows_index);
  std::vector<int> fold_local;
  for (int i : train_rows_index) {
    const long l = info.owners.local(static_cast<std::size_t>(i));
    if (l >= 0) fold_local.push_back(static_cast<int>(l));
  }
  cv::Mat1f fold_rows(static_cast<int>(fold_local.size()), rows.cols);
  std::vector<int> fold_labels;
  for (std::size_t k = 0; k < fold_local.size(); ++k) rows.row(fold_local[k]).copyTo(fold_rows.row(static_cast<int>(k)));
  for (int i : train_rows_index) fold_labels.push_back(labels[static_cast<std::size_t>(i)]);
  const auto fold_pos = std::count(fold_labels.begin(), fold_labels.end(), 1);
  // A held-out fold may hold one class only: the pooled scores need both (checked below).
  if (fold_pos == 0 || fold_pos == static_cast<long>(fold_labels.size())) {
    throw Error("group fold " + std::to_string(f + 1) + " of " + std::to_string(folds) +
                " leaves a class empty: give more recordings or clips, or fewer folds");
  }
  return train_boosted_model(fold_rows, fold_labels, inner, fold_progress, nullptr, nullptr, fold_info);
}

/// Appends the held-out rows `held` of a fold's `model` to `pooled`: their labels, and their scores after
/// each new round and at the end.
void pool_held_out(const BoostedModel& model, const cv::Mat1f& rows, const std::vector<int>& labels,
                   const TrainingRowInfo& info, const std::vector<int>& held, const BoostTrainingParams& params,
                   PooledOutOfFold& pooled) {
  // The model names the spec's features; the rows hold the pool's columns (when there is a pool).
  const std::vector<WeakClassifier> weak_on_rows = on_row_columns(model.weak_classifiers(), params);
  // With continued training the fold's model starts with params.init: the rounds are the new ones.
  const std::size_t first = params.init.size();
  const std::size_t rounds = weak_on_rows.size() - first;
  if (pooled.per_round.size() < rounds) pooled.per_round.resize(rounds);
  // Scores of the held-out rows held here after each round, then of every held-out row in order.
  std::vector<std::vector<double>> local_round(rounds);
  std::vector<double> local_pooled;
  std::vector<std::size_t> held_index;
  for (int i : held) {
    held_index.push_back(static_cast<std::size_t>(i));
    pooled.labels.push_back(labels[static_cast<std::size_t>(i)]);
    const long l = info.owners.local(static_cast<std::size_t>(i));
    if (l < 0) continue;
    const float* row = rows[static_cast<int>(l)];
    double h = 0.0;
    for (std::size_t r = 0; r < first; ++r) h += weak_on_rows[r].respond_row(row, model.bins());
    for (std::size_t r = 0; r < rounds; ++r) {
      h += weak_on_rows[first + r].respond_row(row, model.bins());
      local_round[r].push_back(h);
    }
    local_pooled.push_back(h);
  }
  for (std::size_t r = 0; r < rounds; ++r) {
    const std::vector<double> whole = info.owners.whole(local_round[r], held_index);
    pooled.per_round[r].insert(pooled.per_round[r].end(), whole.begin(), whole.end());
  }
  const std::vector<double> whole = info.owners.whole(local_pooled, held_index);
  pooled.scores.insert(pooled.scores.end(), whole.begin(), whole.end());
}

/// The final model's validation figures: the folds' pooled out-of-fold figures.
void record_pooled_validation(BoostedModel& model, const PooledOutOfFold& pooled, const BoostTrainingParams& params,
                              std::size_t folds, std::size_t group_count) {
  TrainingRecord& record = model.training();
  record.parameters = parameter_record(params);
  const std::string source = std::to_string(folds) + " folds of whole groups (" + std::to_string(group_count) +
                             " groups, seed " + std::to_string(params.seed) +
                             "): figures of the folds' models on their held-out groups, pooled";
  record.validation = ValidationFigures{};
  record.validation.source = source;
  record.validation.positives = static_cast<std::size_t>(std::count(pooled.labels.begin(), pooled.labels.end(), 1));
  record.validation.negatives = pooled.labels.size() - record.validation.positives;
  for (std::size_t r = 0; r < pooled.per_round.size(); ++r) {
    const int round = static_cast<int>(r + 1);
    if (round % params.report_every != 0 && r + 1 != pooled.per_round.size()) continue;
    RoundFigures f;
    f.round = round;
    f.feature = model.weak_classifiers()[params.init.size() + r].feature;
    f.validation = summarise_roc(pooled.per_round[r], pooled.labels);
    f.roc = roc_at_far_levels(roc_curve(pooled.per_round[r], pooled.labels));
    record.validation.rounds.push_back(f);
  }
  record_validation(model, record.validation, pooled.scores, pooled.labels, params, source);
}

}  // namespace

BoostedModel train_with_group_folds(const cv::Mat1f& rows, const std::vector<int>& labels,
                                    const BoostTrainingParams& params, const TrainingProgressFn& progress,
                                    const TrainingRowInfo& info) {
  validate_training_params(params);
  if (info.groups.size() != labels.size()) throw Error("group folds need the rows' groups");
  // Groups dealt to folds in a seeded order: every group in exactly one fold.
  const DenseGroups groups = dense_groups(info.groups);
  // Fewer groups than folds: one fold per group.
  const auto folds = std::min(static_cast<std::size_t>(params.folds), groups.count);
  if (folds < 2) throw Error("group folds need at least 2 groups (" + std::to_string(groups.count) + " given)");
  const std::vector<std::size_t> shuffled = seeded_permutation(groups.count, params.seed);
  std::vector<std::size_t> fold_of_group(groups.count);
  for (std::size_t k = 0; k < shuffled.size(); ++k) fold_of_group[shuffled[k]] = k % folds;
  auto fold_of = [&](std::size_t row) { return fold_of_group[groups.of_row[row]]; };
  auto augmented = [&](std::size_t row) { return !info.augmented.empty() && info.augmented[row]; };

  BoostTrainingParams inner = params;
  inner.folds = 0;
  inner.validation_fraction = 0.0;
  inner.early_stopping = 0;
  inner.calibration = "none";
  PooledOutOfFold pooled;
  for (std::size_t f = 0; f < folds; ++f) {
    std::vector<int> train_rows_index, held;
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if (fold_of(i) != f) {
        train_rows_index.push_back(static_cast<int>(i));
      } else if (!augmented(i)) {
        held.push_back(static_cast<int>(i));
      }
    }
    const TrainingProgressFn fold_progress = [&](const TrainingProgress& p) {
      if (!progress) return;
      TrainingProgress q = p;
      q.fold = static_cast<int>(f + 1);
      q.folds = static_cast<int>(folds);
      q.left_s = p.left_s + p.round_s * p.rounds * static_cast<double>(folds - f);
      progress(q);
    };
    const BoostedModel model = train_fold(rows, labels, info, train_rows_index, inner, f, folds, fold_progress);
    pool_held_out(model, rows, labels, info, held, params, pooled);
  }
  const auto pooled_pos = std::count(pooled.labels.begin(), pooled.labels.end(), 1);
  if (pooled_pos == 0 || pooled_pos == static_cast<long>(pooled.labels.size())) {
    throw Error("group folds: the held-out samples lack a class");
  }
  // The final model on every row; its validation figures are the folds' pooled out-of-fold figures.
  const TrainingProgressFn final_progress = [&](const TrainingProgress& p) {
    if (!progress) return;
    TrainingProgress q = p;
    q.fold = static_cast<int>(folds + 1);
    q.folds = static_cast<int>(folds);
    progress(q);
  };
  TrainingRowInfo final_info;
  final_info.owners = info.owners;
  BoostedModel model = train_boosted_model(rows, labels, inner, final_progress, nullptr, nullptr, final_info);
  record_pooled_validation(model, pooled, params, folds, groups.count);
  return model;
}

}  // namespace rdsf
