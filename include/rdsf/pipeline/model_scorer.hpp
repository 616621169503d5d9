#pragma once
// Scores candidates with a model by computing only the features it reads (features_read, FeatureSubset):
// the histograms of the regions those pairs name, then the pairs, then H(x). The score is bit for bit the
// model's score of the full feature vector: same values, same weak classifiers in the same order (the
// model is kept with its weak classifiers renumbered to positions in the subset). A model without stumps
// is evaluated as a BinnedForest of that compact model (the same bits, classifier/binned_forest.hpp).
//
// The crop's mirror m(x, y) = crop(W - 1 - x, y) is read without flipping the crop when the spec's regions
// are each other's mirror images (both known layouts at their defaults): a region's histogram does not depend
// on where in the region a pixel lies, so the mirror's region r holds the crop's region mirror(r), and a
// pair's coefficient is symmetric (bins where either root is 0 add exactly +0, products commute), so the
// mirror's feature (i, j) is the crop's feature (mirror(i), mirror(j)). One pass over the crop for the
// union of both features' regions gives both, bit for bit what the features of the flipped crop are.
#include <optional>
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
  /// Each candidate's features() values as a row of `crop_features` and, when `mirror_features` is given, its
  /// mirror's as a row of that (compute_with_mirror: one pass); what score_rows and MirrorScoring read.
  void compute(const std::vector<Candidate>& candidates, cv::Mat1f& crop_features, cv::Mat1f* mirror_features) const;
  /// H(x) of each row of features() values.
  std::vector<double> score_rows(const cv::Mat1f& rows) const;
  /// H(x) of the crop mirrored left to right: score(m) with m(x, y) = crop(W - 1 - x, y).
  double mirrored_score(const cv::Mat1w& crop_depth_mm) const;
  /// The features() values of a crop and of its mirror (each features().size() values): from one pass over
  /// the crop when the spec allows (the header comment), else the mirror flipped and computed; the same bits.
  void compute_with_mirror(const cv::Mat1w& crop_depth_mm, float* crop_values, float* mirror_values) const;
  /// True when compute_with_mirror() reads the mirror from the crop itself (false: it flips).
  bool mirrors_by_regions() const { return with_mirror_.has_value(); }

 private:
  FeatureSubset subset_;
  /// The features() and their mirror images' counterparts (none when some region has no mirror image in the
  /// spec), and per features() position the places of a crop's value and of its mirror's value in it.
  std::optional<FeatureSubset> with_mirror_;
  std::vector<int> crop_at_, mirror_at_;
  BoostedModel compact_;  ///< the model reading positions in subset_ instead of feature indices
  bool binned_ = false;   ///< compact_ has no stumps: forest_ scores it
  BinnedForest forest_;   ///< compact_ on rows of subset_.size() bins
};

}  // namespace rdsf
