#include "rdsf/labeling/active_learning.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "rdsf/classifier/boost_training.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/features/rdsf_extractor.hpp"

namespace rdsf {

std::vector<std::size_t> most_uncertain_first(const std::vector<double>& probabilities) {
  std::vector<std::size_t> order(probabilities.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return uncertainty(probabilities[a], kDefaultOperatingProbability) <
           uncertainty(probabilities[b], kDefaultOperatingProbability);
  });
  return order;
}

BoostTrainingParams loop_boosting() {
  BoostTrainingParams p;
  p.rounds = 60;
  p.folds = 0;
  return p;
}

std::optional<BoostedModel> train_loop_model(const cv::Mat1f& rows, const std::vector<int>& labels,
                                             const std::vector<SampleOrigin>& origins, const FeatureSpec& spec,
                                             const LoopTrainingParams& params, const std::string& name) {
  const auto positives = static_cast<int>(std::count(labels.begin(), labels.end(), 1));
  const int negatives = static_cast<int>(labels.size()) - positives;
  if (positives < params.min_per_class || negatives < params.min_per_class) return std::nullopt;
  BoostTrainingParams p = params.boost;
  p.feature_spec = spec;
  TrainingRowInfo info;
  if (!origins.empty()) info.groups = sample_groups(origins, params.group_frames).group;
  BoostedModel model;
  try {
    model = train_boosted_model(rows, labels, p, {}, nullptr, nullptr, info);
  } catch (const Error&) {
    // Too few groups for a held-out part with both classes (early in a session): split by sample instead.
    if (info.groups.empty()) throw;
    model = train_boosted_model(rows, labels, p, {}, nullptr, nullptr, TrainingRowInfo{});
  }
  model.set_identity(name, 0, "", "");
  return model;
}

cv::Mat1f SampleFeatureCache::rows(const SampleSet& set, const std::vector<std::size_t>& indices, int threads) {
  std::vector<std::size_t> missing;
  for (std::size_t i : indices) {
    if (rows_.count(set.records()[i].id) == 0) missing.push_back(i);
  }
  if (!missing.empty()) {
    const cv::Mat1f computed = set.features(RdsfExtractor(set.feature_spec()), missing, threads);
    for (std::size_t k = 0; k < missing.size(); ++k) {
      rows_[set.records()[missing[k]].id] = computed.row(static_cast<int>(k)).clone();
    }
  }
  cv::Mat1f out(static_cast<int>(indices.size()), set.feature_spec().dimension());
  for (std::size_t k = 0; k < indices.size(); ++k) {
    rows_.at(set.records()[indices[k]].id).copyTo(out.row(static_cast<int>(k)));
  }
  return out;
}

std::optional<BoostedModel> train_loop_model(const SampleSet& set, const LoopTrainingParams& params,
                                             const std::string& name, SampleFeatureCache* cache) {
  std::vector<int> labels;
  std::vector<SampleOrigin> origins;
  std::vector<std::size_t> used;
  for (std::size_t i = 0; i < set.records().size(); ++i) {
    const SampleRecord& r = set.records()[i];
    // the model's answers and the labels along their tracks (--propagate-model-answers)
    if (!params.train_on_model_answers && (r.origin == "labeler-model" || r.origin == "labeler-model-track")) continue;
    labels.push_back(r.label);
    origins.push_back({r.source, r.frame});
    used.push_back(i);
  }
  const auto positives = static_cast<int>(std::count(labels.begin(), labels.end(), 1));
  if (positives < params.min_per_class || static_cast<int>(labels.size()) - positives < params.min_per_class) {
    return std::nullopt;
  }
  const cv::Mat1f rows =
      cache ? cache->rows(set, used, params.boost.threads) : set.features(RdsfExtractor(set.feature_spec()), used, params.boost.threads);
  return train_loop_model(rows, labels, origins, set.feature_spec(), params, name);
}

std::vector<double> out_of_fold_probabilities(const cv::Mat1f& rows, const std::vector<int>& labels,
                                              const std::vector<SampleOrigin>& origins, const FeatureSpec& spec,
                                              const LoopTrainingParams& params, int folds) {
  if (folds < 2) throw Error("out-of-fold scores need at least 2 folds");
  const std::vector<std::size_t> group = sample_groups(origins, params.group_frames).group;
  std::vector<double> p(labels.size(), 0.5);
  for (int f = 0; f < folds; ++f) {
    std::vector<int> train_rows, held;
    for (std::size_t i = 0; i < labels.size(); ++i) {
      (static_cast<int>(group[i] % static_cast<std::size_t>(folds)) == f ? held : train_rows).push_back(static_cast<int>(i));
    }
    if (held.empty()) continue;
    cv::Mat1f part(static_cast<int>(train_rows.size()), rows.cols);
    std::vector<int> part_labels;
    std::vector<SampleOrigin> part_origins;
    for (std::size_t k = 0; k < train_rows.size(); ++k) {
      rows.row(train_rows[k]).copyTo(part.row(static_cast<int>(k)));
      part_labels.push_back(labels[static_cast<std::size_t>(train_rows[k])]);
      part_origins.push_back(origins[static_cast<std::size_t>(train_rows[k])]);
    }
    const std::optional<BoostedModel> model = train_loop_model(part, part_labels, part_origins, spec, params);
    if (!model) continue;
    for (int i : held) p[static_cast<std::size_t>(i)] = model->probability(model->score(rows[i]));
  }
  return p;
}

}  // namespace rdsf
