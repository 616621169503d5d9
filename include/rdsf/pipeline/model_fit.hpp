#pragma once
// Whether a model may score the candidates a detector cuts, checked in one place for every program that
// runs a model on candidates (rdsf-detect through PeoplePipeline, rdsf-mine --model, rdsf-label --model):
//   - the same feature spec (the features, the crop size and its sampling), and
//   - when the model records it (format 3), crops cut the same way: window_box and window_scale
//     (candidates/crop_provenance.hpp).
// A model trained on other crops loses accuracy without a word, so both are errors, never warnings.
#include <string>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/analysis/frame_analyser.hpp"

namespace rdsf {

/// Empty when `model` fits `detector`; else one line saying what differs, with both values.
std::string model_fit_problem(const BoostedModel& model, const AnalyserParams& detector);

/// Throws Error naming the model file (or name) and what differs.
void check_model_fits(const BoostedModel& model, const AnalyserParams& detector);

}  // namespace rdsf
