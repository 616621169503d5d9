#pragma once
// How the pipeline turns a model's H(x) of each candidate's crop into the candidate's score (PipelineParams):
//   the model mirror-averaged, (H(crop) + H(mirror)) / 2, when mirror_average_for(model);
//   a model adapted to a room with inherited rounds (inherited_mirror_rounds_for(model) = k > 0): those k
//     averaged and its own on the crop alone, H(crop) + (H_k(mirror) - H_k(crop)) / 2, H_k the sum of the
//     first k weak responses of the same features (ModelScorer::score_features(values, k));
//   else H(crop).
// The mirror's features come with the crop's (ModelScorer::compute_with_mirror: one pass over the crop).
// One place for PeoplePipeline and for rdsf-detect's further models, which score the same candidates.
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/candidates/candidate.hpp"
#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/pipeline/model_scorer.hpp"

namespace rdsf {

struct PipelineParams;

class MirrorScoring {
 public:
  MirrorScoring(const BoostedModel& model, const PipelineParams& params);
  /// True when apply() reads the candidates' mirrors (else it leaves the scores as they are).
  bool reads_mirror() const { return whole_ || inherited_rounds_ > 0; }
  /// `scores`: each candidate's H(x) of its crop by `scorer` (a ModelScorer of the same model), made the
  /// candidate's score as above. `crop_features`, `mirror_features`: row i the scorer.features() values of
  /// candidate i's crop and of its mirror (ModelScorer::compute_with_mirror); empty: computed here.
  void apply(const ModelScorer& scorer, const std::vector<Candidate>& candidates, const cv::Mat1f& crop_features,
             const cv::Mat1f& mirror_features, std::vector<double>& scores) const;

 private:
  bool whole_ = false;                ///< the whole model mirror-averaged
  std::size_t inherited_rounds_ = 0;  ///< k above; 0: none averaged apart
};

}  // namespace rdsf
