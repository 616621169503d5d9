#pragma once
// The pieces of active learning that the labeler's loop (rdsf-label --loop), the review (rdsf-review) and
// their benchmark share:
//   uncertainty  |P(person) - 0.5| (- the model's operating point, when it states one): the candidates
//                closest to it are asked first (uncertainty sampling, the smallest margin of a two-class model);
//   suspicion    the probability that a stored label is wrong under a model: 1 - P for a person, P for a
//                not-person; the review shows the most suspicious first;
//   loop model   a model trained in-process on the labelled rows: the trainer's defaults (Real AdaBoost,
//                depth-2 trees, learning rate 0.5, Platt calibration) with fewer rounds and a held-out
//                fraction by group (recording and frame block), so that a retrain costs well under a second
//                at labelling sizes.
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/classifier/boost_training.hpp"
#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/dataset/sample_groups.hpp"
#include "rdsf/dataset/sample_set.hpp"

namespace rdsf {

/// How far a candidate is from where its model is read: |P - boundary|, the boundary being the model's
/// operating point (BoostedModel::operating_probability, 0.5 for a model that states none). Smallest first
/// is the most uncertain.
inline double uncertainty(double probability, double boundary) { return std::abs(probability - boundary); }

/// Indices of `probabilities` closest to 0.5 first; ties in index order.
std::vector<std::size_t> most_uncertain_first(const std::vector<double>& probabilities);

/// Probability that `label` (1 person, 0 not) is wrong when the model says P(person) = probability.
inline double suspicion(int label, double probability) { return label == 1 ? 1.0 - probability : probability; }

/// Boosting of the labeler's loop: rdsf-train's defaults (depth 2, learning rate 0.5), 60 rounds (the
/// trainer's default is 100) and one held-out part (no folds) for the Platt calibration.
BoostTrainingParams loop_boosting();

struct LoopTrainingParams {
  BoostTrainingParams boost = loop_boosting();  ///< its threads: 0 = one per core (no effect on the result)
  int group_frames = 15;             ///< frames per validation group (a synthetic clip's length)
  int min_per_class = 5;             ///< fewer positives or negatives: no model yet
  /// Train on samples the model answered too (origin "labeler-model", and "labeler-model-track" along their
  /// tracks); off: a model's answers never teach
  /// its successor (self-training made the loop's later models answer persons n: docs/labeler.md).
  bool train_on_model_answers = false;
};

/// A model trained on `rows` (features of `spec`) with `labels` (1/0); `origins` (one per row, may be
/// empty) give the validation groups. No value when a class has fewer than min_per_class rows. The model
/// is named `name` (version 0: not saved).
std::optional<BoostedModel> train_loop_model(const cv::Mat1f& rows, const std::vector<int>& labels,
                                             const std::vector<SampleOrigin>& origins, const FeatureSpec& spec,
                                             const LoopTrainingParams& params, const std::string& name = "loop");

/// Feature rows of a growing set's samples by id, so that each retrain computes only the new samples'.
class SampleFeatureCache {
 public:
  /// Rows of the samples `indices` of `set` (records() positions), computing those not seen before.
  cv::Mat1f rows(const SampleSet& set, const std::vector<std::size_t>& indices, int threads = 0);

 private:
  std::unordered_map<std::int64_t, cv::Mat1f> rows_;
};

/// The same on the samples in force of `set` (without the model's answers unless train_on_model_answers),
/// features computed from its crops (only the new ones when a cache is given).
std::optional<BoostedModel> train_loop_model(const SampleSet& set, const LoopTrainingParams& params,
                                             const std::string& name = "loop", SampleFeatureCache* cache = nullptr);

/// P(person) of every row under a model that never saw it: `folds` models, each trained on all groups but
/// one fold of them (group g is in fold g % folds; groups from `origins` as above), score the rows held
/// out. A model trained on the rows themselves learns their wrong labels too (the review benchmark: 29% of
/// planted flips in the first 5% shown, against 86% out of fold, docs/review.md). Rows of a fold whose
/// training part lacks a class get 0.5.
std::vector<double> out_of_fold_probabilities(const cv::Mat1f& rows, const std::vector<int>& labels,
                                              const std::vector<SampleOrigin>& origins, const FeatureSpec& spec,
                                              const LoopTrainingParams& params, int folds = 5);

}  // namespace rdsf
