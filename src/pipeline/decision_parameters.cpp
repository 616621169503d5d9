// The table of the PipelineParams a user sets (core/parameter_table.hpp): what makes a candidate a person.
#include "rdsf/pipeline/people_pipeline.hpp"

namespace rdsf {

const ParameterTable<PipelineParams>& decision_parameters() {
  using P = PipelineParams;
  static const ParameterTable<P> table = {
      parameter("threshold", &P::probability_threshold,
                "a candidate is a person when its calibrated P(person) >= this (0 < P < 1; 0: the model's "
                "operating point, 0.5 for a model that states none)", Range::from_below(0.0, 1.0)),
      parameter("mirror-average", &P::mirror_average,
                "a candidate's score is the mean of H(x) of its depth crop and of the crop mirrored left to right, "
                "except with a model adapted to a room by rdsf-adapt (see --mirror-average-inherited; 0: the crop "
                "alone, the thesis's way)",
                {}, std::optional<bool>(false)),
      parameter("mirror-average-inherited", &P::mirror_average_inherited,
                "with --mirror-average, a model adapted to a room scores the rounds it continued mirror-averaged and "
                "its own rounds on the crop alone (0: the adapted model on the crop alone, as before 2026-12-07)",
                {}, std::optional<bool>(false)),
      parameter("max-height", &P::max_person_height_cm,
                "no person is taller than this (cm) at their own depth (the median of the candidate's crop's "
                "readings): taller candidates (door frames, curtains, far walls) are dropped before scoring; "
                "detection only, never mining or labelling (0 = off, the thesis)",
                Range::at_least(0), std::optional<double>(0.0)),
      parameter("suppress-duplicates", &P::suppress_duplicates,
                "of a whole object and a piece cut out of it that both pass the threshold only the higher-scoring "
                "one is a person (0: both; with --split-head-keep-whole 1 or --split-keep-whole 1)"),
  };
  return table;
}

}  // namespace rdsf
