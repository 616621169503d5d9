#pragma once
// Scores candidates with a model by computing only the features it reads (features_read, FeatureSubset):
// the histograms of the regions those pairs name, then the pairs, then H(x). The score is bit for bit the
// model's score of the full feature vector: same values, same weak classifiers in the same order (the
// model is kept with its weak classifiers renumbered to positions in the subset). A model without stumps
// is evaluated as a BinnedForest of that compact model (the same bits, classifier/binned_forest.hpp).
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/candidates/candidate.hpp"
#include "rdsf/classifier/binned_forest.hpp"
#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/features/feature_subset.hpp"

namespace rdsf {

class ModelScorer {
 public:
  /// Scores with `model` (copied) in its own feature spec.
  explicit ModelScorer(const BoostedModel& model);

  const FeatureSpec& feature_spec() const { return subset_.spec(); }
  /// The features computed per candidate.
  const FeatureSubset& features() const { return subset_; }

  /// H(x) of one window-sized masked depth crop (throws Error on another size). Thread-safe.
  double score(const cv::Mat1w& crop_depth_mm) const;
  /// P(person) of one crop: the model's calibration of score(crop).
  double probability(const cv::Mat1w& crop_depth_mm) const { return compact_.probability(score(crop_depth_mm)); }
  /// H(x) from the features() values of one crop (features().size() values).
  double score_features(const float* values) const {
    return binned_ ? forest_.score(values) : compact_.score(values);
  }
  /// The first `rounds` weak classifiers' sum alone from the same values: bit for bit the score of a model
  /// of those weak classifiers (BoostedModel::score(features, rounds)).
  double score_features(const float* values, std::size_t rounds) const {
    return binned_ ? forest_.score(values, rounds) : compact_.score(values, rounds);
  }
  /// H(x) of every candidate's depth crop.
  std::vector<double> score(const std::vector<Candidate>& candidates) const;
  /// The same, keeping each crop's features() values as a row of `crop_features` (what MirrorScoring reads).
  std::vector<double> score(const std::vector<Candidate>& candidates, cv::Mat1f& crop_features) const;
  /// H(x) of the crop mirrored left to right: score(m) with m(x, y) = crop(W - 1 - x, y).
  double mirrored_score(const cv::Mat1w& crop_depth_mm) const;
  /// Mirror averaging (PipelineParams::mirror_average): (score(crop) + mirrored_score(crop)) / 2 per
  /// candidate, from `scores`, each candidate's score(crop) as computed before.
  void average_with_mirror(const std::vector<Candidate>& candidates, std::vector<double>& scores) const;
  /// This scorer's model as a part of the model that gave `scores` (its first weak classifiers, the same
  /// feature spec): each candidate's part scored mirror-averaged instead of on the crop alone,
  /// scores[i] += (mirrored_score(crop) - part_of_crop[i]) / 2 (PipelineParams::mirror_average_inherited),
  /// part_of_crop[i] the part's score(crop), which the whole model's scoring of the crop gave already.
  void average_part_with_mirror(const std::vector<Candidate>& candidates, const std::vector<double>& part_of_crop,
                                std::vector<double>& scores) const;

 private:
  FeatureSubset subset_;
  BoostedModel compact_;  ///< the model reading positions in subset_ instead of feature indices
  bool binned_ = false;   ///< compact_ has no stumps: forest_ scores it
  BinnedForest forest_;   ///< compact_ on rows of subset_.size() bins
};

}  // namespace rdsf
