#include "rdsf/pipeline/holdout_check.hpp"

#include <algorithm>
#include <cmath>

#include "rdsf/classifier/roc_metrics.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/pipeline/mirror_scoring.hpp"
#include "rdsf/pipeline/model_scorer.hpp"

namespace rdsf {

std::vector<std::string> later_half(const std::vector<std::string>& names_in_order) {
  return std::vector<std::string>(names_in_order.begin() + static_cast<std::ptrdiff_t>(names_in_order.size() / 2),
                                  names_in_order.end());
}

std::size_t people_found_at_fppf(const std::vector<double>& person_scores, const std::vector<double>& other_scores,
                                 std::size_t frames, double max_fppf) {
  if (frames < 1) throw Error("people_found_at_fppf: no frames");
  const auto allowed = static_cast<std::size_t>(std::floor(max_fppf * static_cast<double>(frames) + 1e-9));
  if (other_scores.size() <= allowed) return person_scores.size();  // roc_curve needs both classes
  if (person_scores.empty()) return 0;
  // At most `allowed` others accepted is FAR <= allowed / others on the candidates' ROC curve.
  std::vector<double> scores = person_scores;
  scores.insert(scores.end(), other_scores.begin(), other_scores.end());
  std::vector<int> labels(person_scores.size(), 1);
  labels.resize(scores.size(), 0);
  const double tar = tar_at_far(roc_curve(scores, labels),
                                static_cast<double>(allowed) / static_cast<double>(other_scores.size()));
  return static_cast<std::size_t>(std::lround(tar * static_cast<double>(person_scores.size())));
}

std::vector<double> detector_scores(const BoostedModel& model, const PipelineParams& params,
                                    const std::vector<cv::Mat1w>& crops) {
  std::vector<Candidate> candidates(crops.size());
  for (std::size_t i = 0; i < crops.size(); ++i) candidates[i].depth_crop = crops[i];
  const ModelScorer scorer(model);
  std::vector<double> scores = scorer.score(candidates);
  MirrorScoring(model, params).apply(scorer, candidates, cv::Mat1f(), cv::Mat1f(), scores);
  return scores;
}

BoostedModel base_as_room_model(BoostedModel base, const RecordedParameters& detection_options,
                                const RecordedParameters& provenance) {
  if (!detection_options.empty()) base.set_detection_options(detection_options);
  RecordedParameters& parameters = base.training().parameters;
  parameters.erase(std::remove_if(parameters.begin(), parameters.end(),
                                  [](const auto& p) { return p.first == kInitWeakClassifiersParameter; }),
                   parameters.end());
  parameters.emplace_back(kInitWeakClassifiersParameter, std::to_string(base.weak_classifiers().size()));
  parameters.insert(parameters.end(), provenance.begin(), provenance.end());
  return base;
}

}  // namespace rdsf
