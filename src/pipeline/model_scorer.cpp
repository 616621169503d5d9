#include "rdsf/pipeline/model_scorer.hpp"

#include <algorithm>
#include <map>
#include <tuple>

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

// Per region of `spec`, the index of its mirror image (x -> W - x - width), or -1 when the spec has none.
std::vector<int> mirror_regions(const FeatureSpec& spec) {
  const std::vector<FeatureRegion> regions = spec.regions();
  std::map<std::tuple<int, int, int, int>, int> index;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    index[{regions[r].x, regions[r].y, regions[r].width, regions[r].height}] = static_cast<int>(r);
  }
  std::vector<int> mirror;
  for (const FeatureRegion& g : regions) {
    const auto it = index.find({spec.window_width_px - g.x - g.width, g.y, g.width, g.height});
    mirror.push_back(it == index.end() ? -1 : it->second);
  }
  return mirror;
}

}  // namespace

ModelScorer::ModelScorer(const BoostedModel& model)
    : subset_(model.feature_spec(), features_read(model)), compact_(renumbered(model, subset_)) {
  binned_ = BinnedForest::supports(compact_);
  if (binned_) forest_ = BinnedForest(compact_, subset_.size());
  const FeatureSpec& spec = subset_.spec();
  const std::vector<int> mirror = mirror_regions(spec);
  if (std::find(mirror.begin(), mirror.end(), -1) != mirror.end()) return;  // flipped instead
  std::vector<int> mirrored, both = subset_.features();
  for (const int f : subset_.features()) {
    int i = 0, j = 0;
    spec.pair_at(f, i, j);
    const int mi = mirror[static_cast<std::size_t>(i)], mj = mirror[static_cast<std::size_t>(j)];
    mirrored.push_back(spec.pair_index(std::min(mi, mj), std::max(mi, mj)));
    both.push_back(mirrored.back());
  }
  with_mirror_.emplace(spec, both);
  for (std::size_t k = 0; k < mirrored.size(); ++k) {
    crop_at_.push_back(with_mirror_->position(subset_.features()[k]));
    mirror_at_.push_back(with_mirror_->position(mirrored[k]));
  }
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

void ModelScorer::compute(const std::vector<Candidate>& candidates, cv::Mat1f& crop_features,
                          cv::Mat1f* mirror_features) const {
  crop_features.create(static_cast<int>(candidates.size()), subset_.size());
  if (mirror_features != nullptr) mirror_features->create(crop_features.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const int r = static_cast<int>(i);
    if (mirror_features == nullptr) {
      subset_.compute(candidates[i].depth_crop, crop_features[r]);
    } else {
      compute_with_mirror(candidates[i].depth_crop, crop_features[r], (*mirror_features)[r]);
    }
  }
}

std::vector<double> ModelScorer::score_rows(const cv::Mat1f& rows) const {
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(rows.rows));
  for (int r = 0; r < rows.rows; ++r) out.push_back(score_features(rows[r]));
  return out;
}

double ModelScorer::mirrored_score(const cv::Mat1w& crop) const {
  thread_local std::vector<float> crop_values, mirror_values;
  crop_values.resize(static_cast<std::size_t>(subset_.size()));
  mirror_values.resize(crop_values.size());
  compute_with_mirror(crop, crop_values.data(), mirror_values.data());
  return score_features(mirror_values.data());
}

void ModelScorer::compute_with_mirror(const cv::Mat1w& crop, float* crop_values, float* mirror_values) const {
  if (!with_mirror_) {
    thread_local cv::Mat1w mirrored;
    subset_.compute(crop, crop_values);
    cv::flip(crop, mirrored, 1);
    subset_.compute(mirrored, mirror_values);
    return;
  }
  thread_local std::vector<float> both;
  both.resize(static_cast<std::size_t>(with_mirror_->size()));
  with_mirror_->compute(crop, both.data());
  for (std::size_t k = 0; k < crop_at_.size(); ++k) {
    crop_values[k] = both[static_cast<std::size_t>(crop_at_[k])];
    mirror_values[k] = both[static_cast<std::size_t>(mirror_at_[k])];
  }
}

}  // namespace rdsf
