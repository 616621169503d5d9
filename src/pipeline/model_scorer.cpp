#include "rdsf/pipeline/model_scorer.hpp"

#include "rdsf/classifier/features_read.hpp"

namespace rdsf {
namespace {

BoostedModel renumbered(const BoostedModel& model, const FeatureSubset& subset) {
  std::vector<WeakClassifier> weak = model.weak_classifiers();
  renumber_features(weak, [&subset](int feature) { return subset.position(feature); });
  BoostedModel compact(model.feature_spec(), model.bins(), std::move(weak));
  compact.set_calibration(model.calibration());
  return compact;
}

}  // namespace

ModelScorer::ModelScorer(const BoostedModel& model)
    : subset_(model.feature_spec(), features_read(model)), compact_(renumbered(model, subset_)) {
  binned_ = BinnedForest::supports(compact_);
  if (binned_) forest_ = BinnedForest(compact_, subset_.size());
}

double ModelScorer::score(const cv::Mat1w& crop) const {
  constexpr int kOnStack = 512;
  float on_stack[kOnStack];
  std::vector<float> on_heap;
  float* values = on_stack;
  if (subset_.size() > kOnStack) {
    on_heap.resize(static_cast<std::size_t>(subset_.size()));
    values = on_heap.data();
  }
  subset_.compute(crop, values);
  return score_features(values);
}

std::vector<double> ModelScorer::score(const std::vector<Candidate>& candidates) const {
  std::vector<double> out;
  out.reserve(candidates.size());
  for (const Candidate& c : candidates) out.push_back(score(c.depth_crop));
  return out;
}

std::vector<double> ModelScorer::score(const std::vector<Candidate>& candidates, cv::Mat1f& crop_features) const {
  crop_features.create(static_cast<int>(candidates.size()), subset_.size());
  std::vector<double> out;
  out.reserve(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    float* row = crop_features[static_cast<int>(i)];
    subset_.compute(candidates[i].depth_crop, row);
    out.push_back(score_features(row));
  }
  return out;
}

double ModelScorer::mirrored_score(const cv::Mat1w& crop) const {
  thread_local cv::Mat1w mirrored;
  cv::flip(crop, mirrored, 1);
  return score(mirrored);
}

void ModelScorer::average_part_with_mirror(const std::vector<Candidate>& candidates,
                                           const std::vector<double>& part_of_crop, std::vector<double>& scores) const {
  for (std::size_t i = 0; i < candidates.size() && i < scores.size() && i < part_of_crop.size(); ++i) {
    scores[i] += 0.5 * (mirrored_score(candidates[i].depth_crop) - part_of_crop[i]);
  }
}

void ModelScorer::average_with_mirror(const std::vector<Candidate>& candidates, std::vector<double>& scores) const {
  for (std::size_t i = 0; i < candidates.size() && i < scores.size(); ++i) {
    scores[i] = 0.5 * (scores[i] + mirrored_score(candidates[i].depth_crop));
  }
}

}  // namespace rdsf
