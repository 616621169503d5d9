#include "rdsf/pipeline/holdout_check.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

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
  if (other_scores.size() <= allowed) return person_scores.size();
  std::vector<double> others = other_scores;
  std::nth_element(others.begin(), others.begin() + static_cast<std::ptrdiff_t>(allowed), others.end(),
                   std::greater<double>());
  const double threshold = others[allowed];  // the (allowed + 1)-th highest: every threshold must pass above it
  return static_cast<std::size_t>(
      std::count_if(person_scores.begin(), person_scores.end(), [&](double s) { return s > threshold; }));
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
