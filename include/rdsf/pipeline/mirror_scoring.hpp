#pragma once
// How the pipeline turns a model's H(x) of each candidate's crop into the candidate's score (PipelineParams):
//   the model mirror-averaged, (H(crop) + H(mirror)) / 2, when mirror_average_for(model);
//   a model adapted to a room with inherited rounds (inherited_mirror_rounds_for(model) = k > 0): those k
//     averaged and its own on the crop alone, H(crop) + (H_k(mirror) - H_k(crop)) / 2, H_k(crop) the sum of
//     the first k weak responses of the crop's features as scored already (no second pass over the crop);
//   else H(crop).
// One place for PeoplePipeline and for rdsf-detect's further models, which score the same candidates.
#include <optional>
#include <vector>

#include "rdsf/candidates/candidate.hpp"
#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/pipeline/model_scorer.hpp"

namespace rdsf {

struct PipelineParams;

class MirrorScoring {
 public:
  MirrorScoring(const BoostedModel& model, const PipelineParams& params);
  /// `scores`: each candidate's H(x) of its crop by `scorer` (a ModelScorer of the same model), made the
  /// candidate's score as above. `crop_features`: row i the scorer.features() values of candidate i's crop
  /// that gave scores[i]; empty: computed here when needed.
  void apply(const ModelScorer& scorer, const std::vector<Candidate>& candidates, const cv::Mat1f& crop_features,
             std::vector<double>& scores) const;

 private:
  bool whole_ = false;                    ///< the whole model mirror-averaged
  std::size_t inherited_rounds_ = 0;      ///< k above; 0: none averaged apart
  std::optional<ModelScorer> inherited_;  ///< the inherited rounds alone, when only they are averaged
};

}  // namespace rdsf
