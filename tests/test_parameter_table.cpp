// The parameter tables (core/parameter_table.hpp): each parameter declared once drives options, recipes, the
// --thesis preset and checks. Defaults pass their own checks, names are unique and kebab-case, a value out of
// range is refused naming the row, and a recipe is read through the same rows.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/classifier/boost_training.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/dataset/recipe.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"
#include "rdsf/synth/synth_params.hpp"
#include "rdsf/tracking/tracker.hpp"
#include "support/test_support.hpp"

namespace rdsf {
namespace {

template <typename Params>
void expect_sound(const ParameterTable<Params>& table) {
  std::set<std::string> names;
  const Params defaults{};
  for (const Parameter<Params>& row : table) {
    EXPECT_TRUE(names.insert(row.name).second) << "two rows named " << row.name;
    EXPECT_EQ(row.name.find('_'), std::string::npos) << row.name << ": option names are kebab-case";
    EXPECT_FALSE(row.help.empty()) << row.name;
    Params p = defaults;
    EXPECT_NO_THROW(row.set(p, row.get(defaults))) << row.name << ": its default fails its own check";
    if (row.thesis) {
      EXPECT_NO_THROW(row.set(p, *row.thesis)) << row.name << ": its thesis value fails its check";
    }
    if (row.classic) {
      EXPECT_NO_THROW(row.set(p, *row.classic)) << row.name << ": its classic value fails its check";
    }
  }
}

TEST(ParameterTable, EveryTableIsSound) {
  expect_sound(analyser_parameters());
  expect_sound(boost_training_parameters());
  expect_sound(tracking_parameters());
  expect_sound(synth::synth_parameters());
  expect_sound(decision_parameters());
  // --thesis scores the crop alone (the one decision row that departs from the thesis).
  EXPECT_FALSE(with_thesis_values(decision_parameters(), PipelineParams{}).mirror_average);
  EXPECT_FALSE(with_thesis_values(decision_parameters(), PipelineParams{}).mirror_average_inherited);
  EXPECT_TRUE(PipelineParams{}.mirror_average_inherited);
  EXPECT_TRUE(PipelineParams{}.mirror_average);
  PipelineParams p;
  EXPECT_THROW(decision_parameters().front().set(p, 1.0), Error);  // threshold: inside (0, 1)
  EXPECT_NO_THROW(decision_parameters().front().set(p, 0.25));
  EXPECT_EQ(p.probability_threshold, 0.25);
}

// A program adds a table's options a stretch at a time (rdsf-synth: --seed between --people and --empty).
TEST(ParameterTable, RowsBetweenTwoNamesAreThatStretch) {
  std::string names;
  for (const auto& row : rows_between(synth::synth_parameters(), "empty", "clip-frames")) names += row.name + " ";
  EXPECT_EQ(names, "empty size fov rgb clip-frames ");
}

TEST(ParameterTable, OutOfRangeValuesAreRefusedNamingTheRow) {
  const ParameterTable<AnalyserParams>& analyser = analyser_parameters();
  AnalyserParams a;
  EXPECT_EQ(test::error_message([&] { find_parameter(analyser, "row-step")->set(a, 0); }), "row-step must be at least 1");
  EXPECT_EQ(test::error_message([&] { find_parameter(analyser, "window-scale")->set(a, 0.0); }), "window-scale must be above 0");
  EXPECT_EQ(test::error_message([&] { find_parameter(analyser, "box")->set(a, std::string("loose")); }),
            "box is fitted or strict, not 'loose'");
  EXPECT_EQ(test::error_message([&] { find_parameter(analyser, "k")->set(a, 2.5); }), "k must be an integer");
  EXPECT_EQ(a.segmentation.row_step, AnalyserParams{}.segmentation.row_step);  // a refused value is not stored
  const ParameterTable<BoostTrainingParams>& boost = boost_training_parameters();
  BoostTrainingParams b;
  EXPECT_EQ(test::error_message([&] { find_parameter(boost, "learning-rate")->set(b, 0.0); }), "learning-rate must be in (0, 1]");
  EXPECT_EQ(test::error_message([&] { find_parameter(boost, "validation-fraction")->set(b, 1.0); }),
            "validation-fraction must be in [0, 1)");
  EXPECT_EQ(test::error_message([&] { find_parameter(boost, "folds")->set(b, 1); }), "folds must be 0 (off) or 2-20");
  EXPECT_EQ(test::error_message([&] { find_parameter(boost, "seed")->set(b, -3); }), "seed must not be negative");
  find_parameter(boost, "depth")->set(b, 3);
  EXPECT_EQ(b.depth, 3);
}

TEST(ParameterTable, ThesisValuesComeFromTheRows) {
  const AnalyserParams thesis = thesis_params();
  EXPECT_FALSE(thesis.segmentation.left_border_jump);
  EXPECT_EQ(thesis.reported_box, BoxKind::strict);
  EXPECT_EQ(thesis.candidates.fit.min_width_ratio, 0.0);
  EXPECT_EQ(thesis.candidates.k, CandidateParams{}.k);  // the thesis's own parameters keep their defaults
  const BoostTrainingParams boost = with_thesis_values(boost_training_parameters(), BoostTrainingParams{});
  EXPECT_EQ(boost.depth, 1);
  EXPECT_EQ(boost.learning_rate, 1.0);
  EXPECT_EQ(boost.rounds, BoostTrainingParams{}.rounds);
}

TEST(ParameterTable, RecipesAreReadThroughTheRows) {
  const Recipe r = parse_recipe("%YAML:1.0\n---\nrecipe: r\nlearning_rate: 0.25\nhistogram_subtraction: 1\n"
                                "smoothing: 0.01\nbackend: native\n",
                                "r.yml");
  EXPECT_EQ(r.params.learning_rate, 0.25);
  EXPECT_TRUE(r.params.histogram_subtraction);
  EXPECT_EQ(r.params.smoothing, 0.01);
  EXPECT_EQ(test::error_message([] { parse_recipe("%YAML:1.0\n---\nlearning_rate: 2\n", "bad.yml"); }),
            "bad.yml: 'learning_rate' must be in (0, 1]");
  EXPECT_EQ(test::error_message([] { parse_recipe("%YAML:1.0\n---\ndepth: 2.5\n", "bad.yml"); }),
            "bad.yml: 'depth' is not an integer");
}

TEST(ParameterTable, ValuesAreShownAsShortAsTheyRoundTrip) {
  EXPECT_EQ(parameter_text(0.3), "0.3");
  EXPECT_EQ(parameter_text(1500.0), "1500");
  EXPECT_EQ(parameter_text(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(parameter_text(true), "1");
  EXPECT_EQ(parameter_key("near-far-boundary"), "near_far_boundary");
}


// The model file's training.parameters come from the rows (boost_training_parameters.cpp): the same keys,
// order and texts the hand-written list gave, so models trained again are the same bytes.
TEST(ParameterTable, ModelFileProvenanceComesFromTheRows) {
  BoostTrainingParams p;  // the defaults: native, depth 2, learning rate 0.5, 5 folds
  p.bins.count = 32;
  const RecordedParameters native{{"backend", "native"}, {"rounds", "100"},     {"bins", "32"},
                                  {"bin_min", "0"},      {"bin_max", "1"},      {"smoothing", "auto (1/N)"},
                                  {"depth", "2"},        {"learning_rate", "0.5"}, {"calibration", "platt"},
                                  {"folds", "5"},        {"weight_trim", "0"},  {"validation_fraction", "0.2"},
                                  {"seed", "1"},         {"report_every", "10"}, {"early_stopping", "0"}};
  EXPECT_EQ(parameter_values(boost_training_parameters(), p), native);

  p.smoothing = 0.001;
  p.histogram_subtraction = true;
  p.folds = 0;
  const RecordedParameters changed = parameter_values(boost_training_parameters(), p);
  EXPECT_EQ(changed[5], (std::pair<std::string, std::string>("smoothing", "0.001")));
  EXPECT_EQ(changed[8], (std::pair<std::string, std::string>("histogram_subtraction", "on")));
  EXPECT_EQ(std::count_if(changed.begin(), changed.end(), [](const auto& kv) { return kv.first == "folds"; }), 0);

  p.backend = BoostBackend::opencv;  // the native backend's options are not recorded
  const RecordedParameters opencv{{"backend", "opencv"}, {"rounds", "100"},  {"calibration", "platt"},
                                  {"weight_trim", "0"},  {"validation_fraction", "0.2"}, {"seed", "1"},
                                  {"report_every", "10"}, {"early_stopping", "0"}};
  EXPECT_EQ(parameter_values(boost_training_parameters(), p), opencv);
}

// The tracker's options are its table's rows: a value out of range is refused naming the option.
TEST(ParameterTable, TrackingRowsCheckTheirValues) {
  TrackingParams t;
  EXPECT_EQ(test::error_message([&] { find_parameter(tracking_parameters(), "histogram-bins")->set(t, 0); }),
            "histogram-bins must be in [1, 256]");
  EXPECT_EQ(test::error_message([&] { find_parameter(tracking_parameters(), "max-missed-frames")->set(t, -1); }),
            "max-missed-frames must be at least 0");
  find_parameter(tracking_parameters(), "threshold-lkh")->set(t, 0.25);
  EXPECT_EQ(t.threshold_lkh, 0.25);
}

}  // namespace
}  // namespace rdsf
