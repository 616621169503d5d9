#include "rdsf/pipeline/mirror_scoring.hpp"

#include "rdsf/pipeline/people_pipeline.hpp"

namespace rdsf {

MirrorScoring::MirrorScoring(const BoostedModel& model, const PipelineParams& params)
    : whole_(params.mirror_average_for(model)) {
  const std::size_t inherited = params.inherited_mirror_rounds_for(model);
  if (inherited == 0) return;
  std::vector<WeakClassifier> weak(model.weak_classifiers().begin(),
                                   model.weak_classifiers().begin() + static_cast<std::ptrdiff_t>(inherited));
  inherited_.emplace(BoostedModel(model.feature_spec(), model.bins(), std::move(weak)));
}

void MirrorScoring::apply(const ModelScorer& scorer, const std::vector<Candidate>& candidates,
                          std::vector<double>& scores) const {
  if (whole_) scorer.average_with_mirror(candidates, scores);
  if (inherited_) inherited_->average_part_with_mirror(candidates, scores);
}

}  // namespace rdsf
