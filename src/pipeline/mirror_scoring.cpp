#include "rdsf/pipeline/mirror_scoring.hpp"

#include <string>

#include "rdsf/core/error.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"

namespace rdsf {
namespace {

void check_rows(const cv::Mat1f& rows, const char* what, std::size_t candidates, int values) {
  if (rows.empty() || (static_cast<std::size_t>(rows.rows) == candidates && rows.cols == values)) return;
  throw Error(std::string("mirror scoring: ") + std::to_string(rows.rows) + " rows of " + std::to_string(rows.cols) +
              " " + what + " features for " + std::to_string(candidates) + " candidates of a model reading " +
              std::to_string(values));
}

}  // namespace

MirrorScoring::MirrorScoring(const BoostedModel& model, const PipelineParams& params)
    : whole_(params.mirror_average_for(model)), inherited_rounds_(params.inherited_mirror_rounds_for(model)) {}

void MirrorScoring::apply(const ModelScorer& scorer, const std::vector<Candidate>& candidates,
                          const cv::Mat1f& crop_features, const cv::Mat1f& mirror_features,
                          std::vector<double>& scores) const {
  if (!reads_mirror()) return;
  const int values = scorer.features().size();
  check_rows(crop_features, "crop", candidates.size(), values);
  check_rows(mirror_features, "mirror", candidates.size(), values);
  const bool given = !crop_features.empty() && !mirror_features.empty();
  std::vector<float> crop_row(given ? 0 : static_cast<std::size_t>(values)), mirror_row(crop_row.size());
  for (std::size_t i = 0; i < candidates.size() && i < scores.size(); ++i) {
    const float* crop = crop_row.data();
    const float* mirror = mirror_row.data();
    if (given) {
      crop = crop_features[static_cast<int>(i)];
      mirror = mirror_features[static_cast<int>(i)];
    } else {
      scorer.compute_with_mirror(candidates[i].depth_crop, crop_row.data(), mirror_row.data());
    }
    if (whole_) {
      scores[i] = 0.5 * (scores[i] + scorer.score_features(mirror));
    } else {
      scores[i] += 0.5 * (scorer.score_features(mirror, inherited_rounds_) - scorer.score_features(crop, inherited_rounds_));
    }
  }
}

}  // namespace rdsf
