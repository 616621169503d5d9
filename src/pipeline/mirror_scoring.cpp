#include "rdsf/pipeline/mirror_scoring.hpp"

#include "rdsf/core/error.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"

namespace rdsf {

MirrorScoring::MirrorScoring(const BoostedModel& model, const PipelineParams& params)
    : whole_(params.mirror_average_for(model)) {
  const std::size_t inherited = params.inherited_mirror_rounds_for(model);
  if (inherited == 0) return;
  inherited_rounds_ = inherited;
  std::vector<WeakClassifier> weak(model.weak_classifiers().begin(),
                                   model.weak_classifiers().begin() + static_cast<std::ptrdiff_t>(inherited));
  inherited_.emplace(BoostedModel(model.feature_spec(), model.bins(), std::move(weak)));
}

void MirrorScoring::apply(const ModelScorer& scorer, const std::vector<Candidate>& candidates,
                          const cv::Mat1f& crop_features, std::vector<double>& scores) const {
  if (whole_) scorer.average_with_mirror(candidates, scores);
  if (!inherited_) return;
  if (!crop_features.empty() && (static_cast<std::size_t>(crop_features.rows) != candidates.size() ||
                                 crop_features.cols != scorer.features().size())) {
    throw Error("mirror scoring: " + std::to_string(crop_features.rows) + " rows of " +
                std::to_string(crop_features.cols) + " features for " + std::to_string(candidates.size()) +
                " candidates of a model reading " + std::to_string(scorer.features().size()));
  }
  std::vector<double> part_of_crop(candidates.size());
  std::vector<float> values(crop_features.empty() ? static_cast<std::size_t>(scorer.features().size()) : 0);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const float* row = values.data();
    if (crop_features.empty()) {
      scorer.features().compute(candidates[i].depth_crop, values.data());
    } else {
      row = crop_features[static_cast<int>(i)];
    }
    part_of_crop[i] = scorer.score_features(row, inherited_rounds_);
  }
  inherited_->average_part_with_mirror(candidates, part_of_crop, scores);
}

}  // namespace rdsf
