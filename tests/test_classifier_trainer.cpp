// rdsf-train as a user runs it: sample sets in, versioned model files out; recipes with too few samples,
// --inspect, --export-text and bad command lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <fstream>
#include <random>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/classifier/model_file.hpp"
#include "rdsf/classifier/roc_metrics.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "classifier_support/toy_sets.hpp"
#include "support/test_support.hpp"

namespace rdsf {
namespace {

namespace fs = std::filesystem;

using test::crop;
using test::make_set;

class TrainerProgram : public ::testing::Test {
 protected:
  void SetUp() override {
    people = dir / "people";
    negatives = dir / "negatives";
    models = dir / "models";
    make_set(people, 1, 60, 1);
    make_set(negatives, 0, 90, 2);
  }
  test::RunResult train(const std::string& arguments) {
    return test::run(test::quote(test::program("rdsf-train")) + " --models-dir " + test::quote(models) + " " + arguments);
  }
  test::TempDir dir{"rdsf-trainer"};
  std::string people, negatives, models;
};

TEST_F(TrainerProgram, AdHocTrainingWritesNumberedVersions) {
  const std::string sets = "--pos " + test::quote(people) + " --neg " + test::quote(negatives);
  const test::RunResult first = train(sets + " --name toy --rounds 5");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.err.find("round 5/5"), std::string::npos) << first.err;
  EXPECT_NE(first.err.find("AUC"), std::string::npos) << first.err;
  EXPECT_NE(first.err.find("wrote " + models + "/toy/v1.yml"), std::string::npos) << first.err;
  const std::string v1 = test::file_text(models + "/toy/v1.yml");
  const test::RunResult second = train(sets + " --name toy --rounds 3 --backend opencv");
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_EQ(test::file_text(models + "/toy/v1.yml"), v1);

  const BoostedModel model = BoostedModel::load("toy", models);
  EXPECT_EQ(model.version(), 2);
  EXPECT_EQ(model.training().backend, "opencv");
  EXPECT_EQ(model.weak_classifiers().size(), 3u);
  const BoostedModel native = BoostedModel::load("toy/v1", models);
  EXPECT_EQ(native.weak_classifiers().size(), 5u);
  ASSERT_EQ(native.training().sample_sets.size(), 2u);
  EXPECT_EQ(native.training().sample_sets[0].role, "pos");
  EXPECT_EQ(native.training().sample_sets[0].used, 60u);
  EXPECT_EQ(native.training().sample_sets[0].manifest_hash, SampleSet::open_read(people).manifest_hash());
  EXPECT_EQ(native.training().sample_sets[1].used, 90u);
  // The model tells the two kinds apart on the sets' own samples.
  const SampleSet pos = SampleSet::open_read(people), neg = SampleSet::open_read(negatives);
  const RdsfExtractor extractor;
  std::vector<double> scores = native.score(pos.features(extractor));
  const std::vector<double> neg_scores = native.score(neg.features(extractor));
  std::vector<int> labels(scores.size(), 1);
  scores.insert(scores.end(), neg_scores.begin(), neg_scores.end());
  labels.resize(scores.size(), 0);
  EXPECT_GT(roc_auc(scores, labels), 0.95);
}

TEST_F(TrainerProgram, RecipeWarnsWhenASetHoldsFewerThanAsked) {
  fs::create_directories(models + "/recipes");
  std::ofstream(models + "/recipes/small.yml") << "%YAML:1.0\n---\nrecipe: small\npositives: 100\nnegatives: 50\n"
                                               << "pos_sets: [ \"" << people << "\" ]\nneg_sets: [ \"" << negatives
                                               << "\" ]\nrounds: 4\nseed: 3\n";
  const test::RunResult r = train("--recipe small --augment off --folds 0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: recipe small asks for 100 positives but the sets hold 60: using all 60"),
            std::string::npos)
      << r.err;
  const BoostedModel model = BoostedModel::load("small", models);
  EXPECT_EQ(model.version(), 1);
  EXPECT_EQ(model.training().train_positives + model.training().validation.positives, 60u);
  EXPECT_EQ(model.training().train_negatives + model.training().validation.negatives, 50u);
  EXPECT_EQ(model.training().recipe.rfind("small (", 0), 0u) << model.training().recipe;
  // The same recipe and seed pick the same samples and give the same model.
  ASSERT_EQ(train("--recipe small --augment off --folds 0").exit_code, 0);
  const BoostedModel again = BoostedModel::load("small", models);
  EXPECT_EQ(again.version(), 2);
  EXPECT_EQ(again.weak_classifiers(), model.weak_classifiers());
}

// A damaged recipe is refused with one line naming it, before OpenCV's reader sees a layout on which it
// never returns (it hung rdsf-train before the recipe reader shared the model files' YamlReader), and a
// mistyped entry is named.
TEST_F(TrainerProgram, DamagedRecipeIsOneLineNamingItNotAHang) {
  fs::create_directories(models + "/recipes");
  const std::string damaged = models + "/recipes/damaged.yml";
  std::ofstream(damaged) << "%YAML:1.0\n---\n  recipe: damaged\n- rounds: 4\n";
  const test::RunResult r = train("--recipe damaged --folds 0");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(damaged + ": line 3: the top-level entries must start in the first column (not a recipe "
                                 "this workbench wrote)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  std::ofstream(models + "/recipes/typo.yml") << "%YAML:1.0\n---\nrecipe: typo\nrounds: many\n";
  const test::RunResult typo = train("--recipe typo --folds 0");
  EXPECT_EQ(typo.exit_code, 1) << typo.err;
  EXPECT_NE(typo.err.find("typo.yml: 'rounds' is not an integer"), std::string::npos) << typo.err;
}

TEST_F(TrainerProgram, InspectShowsHeaderFiguresAndCellPairs) {
  ASSERT_EQ(train("--pos " + test::quote(people) + " --neg " + test::quote(negatives) + " --name toy --rounds 6")
                .exit_code,
            0);
  const test::RunResult r = train("--inspect toy --top 3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("model        toy v1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("format       rdsf-model version " + std::to_string(kModelFormatVersion)), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("AUC"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("calibration  platt: P(person) = 1 / (1 + exp(-("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("by P(person)  P>=0.1: TAR"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("most used features"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(row "), std::string::npos) << r.out;
  const test::RunResult missing = train("--inspect nothing-here");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("nothing-here"), std::string::npos) << missing.err;
}

TEST_F(TrainerProgram, ExportTextWritesTheChosenSamples) {
  const std::string out = dir / "samples.txt";
  const std::string args = "--pos " + test::quote(people) + " --neg " + test::quote(negatives) +
                           " --positives 10 --negatives 20 --export-text " + test::quote(out);
  const test::RunResult r = train(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out);
  std::string line;
  int lines = 0, positives = 0;
  while (std::getline(in, line)) {
    std::istringstream tokens(line);
    int label = -1;
    tokens >> label;
    positives += label == 1 ? 1 : 0;
    int values = 0;
    float v = 0;
    while (tokens >> v) ++values;
    EXPECT_EQ(values, 8128);
    ++lines;
  }
  EXPECT_EQ(lines, 30);
  EXPECT_EQ(positives, 10);
  EXPECT_EQ(train(args).exit_code, 1);  // never replaced without --force
  EXPECT_EQ(train(args + " --force").exit_code, 0);
}

TEST_F(TrainerProgram, BadCommandLinesFailWithOneLine) {
  const test::RunResult none = train("");
  EXPECT_EQ(none.exit_code, 2);
  const test::RunResult recipe = train("--recipe nonexistent");
  EXPECT_EQ(recipe.exit_code, 1);
  EXPECT_NE(recipe.err.find("no such recipe"), std::string::npos) << recipe.err;
  const test::RunResult name = train("--pos " + test::quote(people) + " --neg " + test::quote(negatives));
  EXPECT_EQ(name.exit_code, 2);  // a wrong command line
  EXPECT_NE(name.err.find("--name"), std::string::npos) << name.err;
  const test::RunResult backend =
      train("--pos " + test::quote(people) + " --neg " + test::quote(negatives) + " --name x --backend gpu");
  EXPECT_EQ(backend.exit_code, 2);  // a value the option's row refuses: a wrong command line
  EXPECT_NE(backend.err.find("--backend 'gpu' is not known"), std::string::npos) << backend.err;
  const test::RunResult set = train("--pos " + test::quote(dir / "nope") + " --neg " + test::quote(negatives) + " --name x");
  EXPECT_EQ(set.exit_code, 1);
  EXPECT_NE(set.err.find("nope"), std::string::npos) << set.err;
  EXPECT_FALSE(fs::exists(models + "/x"));
}

TEST_F(TrainerProgram, RectSpecSetsTrainARectModelOnAFeaturePool) {
  const std::string people_rect = dir / "people-rect", negatives_rect = dir / "negatives-rect";
  make_set(people_rect, 1, 60, 1, FeatureSpec::rect());
  make_set(negatives_rect, 0, 90, 2, FeatureSpec::rect());
  const auto result = train("--pos " + test::quote(people_rect) + " --neg " + test::quote(negatives_rect) +
                            " --name rect --rounds 5 --feature-pool 3000 --threads 1");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("feature pool of 3000 of the 120786 features of rdsf-rect"), std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find("rects "), std::string::npos) << result.err;  // progress names the squares
  const BoostedModel model = BoostedModel::load("rect", models);
  EXPECT_EQ(model.feature_spec(), FeatureSpec::rect());
  ASSERT_EQ(model.weak_classifiers().size(), 5u);
  // The weak classifiers name features of the spec (not pool columns): the same score from the crops'
  // full vectors as from the training's own figures.
  const SampleSet pos = SampleSet::open_read(people_rect);
  const RdsfExtractor extractor(FeatureSpec::rect());
  const std::vector<double> scores = model.score(pos.features(extractor));
  const double mean = std::accumulate(scores.begin(), scores.end(), 0.0) / static_cast<double>(scores.size());
  EXPECT_GT(mean, 0.0);  // positives score as people
  const auto& parameters = model.training().parameters;
  EXPECT_NE(std::find(parameters.begin(), parameters.end(), std::make_pair(std::string("feature_pool"), std::string("3000"))),
            parameters.end());
}

TEST_F(TrainerProgram, SetsOfAnotherSpecAreRefusedNamingBoth) {
  const std::string negatives_rect = dir / "negatives-rect";
  make_set(negatives_rect, 0, 20, 2, FeatureSpec::rect());
  auto result = train("--pos " + test::quote(people) + " --neg " + test::quote(negatives_rect) + " --name mixed --rounds 2");
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_NE(result.err.find("rdsf-rect/1"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("rdsf/1"), std::string::npos) << result.err;
  result = train("--pos " + test::quote(people) + " --neg " + test::quote(negatives) +
                 " --name asked --rounds 2 --feature-spec rdsf-rect");
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_NE(result.err.find("differs from the training's"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(models) / "mixed"));
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(models) / "asked"));
}

TEST(FeatureSpecOption, UnknownNamesAndParametersAreUsageErrorsInEveryProgram) {
  const test::TempDir dir("rdsf-spec-option");
  const std::string out = dir / "out";
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"rdsf-mine", "--source " + test::quote(out) + " --out " + test::quote(out)},
      {"rdsf-label", "--source " + test::quote(out) + " --out " + test::quote(out) + " --answers /dev/null"},
      {"rdsf-detect", "--source " + test::quote(out) + " --out " + test::quote(out + ".csv")},
      {"rdsf-train", "--pos " + test::quote(out) + " --neg " + test::quote(out) + " --name x --models-dir " +
                         test::quote(out)}};
  for (const auto& [program, arguments] : runs) {
    for (const char* spec : {"hog", "rdsf-rect:size=3", "rdsf:cell=7"}) {
      const auto result = test::run(test::quote(test::program(program)) + " " + arguments + " --feature-spec " + spec);
      EXPECT_EQ(result.exit_code, 2) << program << " " << spec << ": " << result.err;
      EXPECT_NE(result.err.find("--feature-spec"), std::string::npos) << result.err;
      EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
      EXPECT_FALSE(std::filesystem::exists(out)) << program;
      EXPECT_FALSE(std::filesystem::exists(out + ".csv")) << program;
    }
  }
}

// Separate validation sets of the same recording are taken when their frames are others: frames named by rank
// (no numbers, e.g. a real recording's lab_* names) are ranked over both sides together, so frames b_* are not
// "the same block" as frames a_* because both rank from 0 on their own side (rdsf-train refused them before).
TEST_F(TrainerProgram, ValidationFramesOfTheSameRecordingNamedByRankAreTakenWhenTheyAreOthers) {
  const std::string early_people = dir / "early-people", early_others = dir / "early-others";
  const std::string late_people = dir / "late-people", late_others = dir / "late-others";
  make_set(early_people, 1, 40, 11, {}, "room", "a_");
  make_set(early_others, 0, 60, 12, {}, "room", "a_");
  make_set(late_people, 1, 10, 13, {}, "room", "b_");
  make_set(late_others, 0, 15, 14, {}, "room", "b_");
  const std::string sets = "--pos " + test::quote(early_people) + " --neg " + test::quote(early_others) +
                           " --rounds 2 --folds 0 --group-frames 1 --validation-pos " + test::quote(late_people) +
                           " --validation-neg " + test::quote(late_others);
  const test::RunResult taken = train(sets + " --name later");
  EXPECT_EQ(taken.exit_code, 0) << taken.err;
  EXPECT_NE(taken.err.find("rdsf-train: wrote "), std::string::npos) << taken.err;
  // The same frames on both sides are still refused.
  const test::RunResult shared = train("--pos " + test::quote(early_people) + " --neg " + test::quote(early_others) +
                                       " --rounds 2 --folds 0 --group-frames 1 --validation-pos " +
                                       test::quote(early_people) + " --validation-neg " + test::quote(late_others) +
                                       " --name same");
  EXPECT_EQ(shared.exit_code, 1) << shared.err;
  EXPECT_NE(shared.err.find("validation sets share 40 groups"), std::string::npos) << shared.err;
}

// The levers of issue "honest figures": refused before any work when they make no sense.
TEST_F(TrainerProgram, BadLeversAreRefusedBeforeAnyWork) {
  const std::string sets = "--pos " + test::quote(people) + " --neg " + test::quote(negatives) + " --name x ";
  const test::RunResult shared = train(sets + "--validation-pos " + test::quote(people) + " --validation-neg " +
                                       test::quote(negatives));
  EXPECT_EQ(shared.exit_code, 1);
  EXPECT_NE(shared.err.find("validation sets share"), std::string::npos) << shared.err;
  const test::RunResult augment = train(sets + "--augment mirror,rotate");
  EXPECT_EQ(augment.exit_code, 2);  // training_data_parameters()' rows: usage errors, before any set is read
  EXPECT_NE(augment.err.find("--augment augmentation 'rotate' is not known"), std::string::npos) << augment.err;
  const test::RunResult copies = train(sets + "--augment mirror --augment-copies 3");
  EXPECT_EQ(copies.exit_code, 2);
  EXPECT_NE(copies.err.find("need shift, scale or occlusion"), std::string::npos) << copies.err;
  const test::RunResult groups = train(sets + "--group-by room");
  EXPECT_EQ(groups.exit_code, 2);
  EXPECT_NE(groups.err.find("--group-by grouping 'room' is not known (recording-block, block or recording)"),
            std::string::npos) << groups.err;
  const test::RunResult frames = train(sets + "--group-frames -1");
  EXPECT_EQ(frames.exit_code, 2);
  EXPECT_NE(frames.err.find("--group-frames must be at least 0"), std::string::npos) << frames.err;
  const test::RunResult depth = train(sets + "--depth 7");
  EXPECT_EQ(depth.exit_code, 2);  // the options' rows check their values: usage errors
  EXPECT_NE(depth.err.find("--depth must be in [1, 4]"), std::string::npos) << depth.err;
  const test::RunResult rate = train(sets + "--learning-rate 1.5");
  EXPECT_EQ(rate.exit_code, 2);
  EXPECT_NE(rate.err.find("--learning-rate must be in (0, 1]"), std::string::npos) << rate.err;
  const test::RunResult calibration = train(sets + "--calibration magic");
  EXPECT_EQ(calibration.exit_code, 2);
  EXPECT_NE(calibration.err.find("'magic' is not known"), std::string::npos) << calibration.err;
  for (const test::RunResult* r : {&shared, &augment, &copies, &groups, &frames, &depth, &rate, &calibration}) {
    // One error line, and it is the last thing printed.
    std::size_t errors = 0;
    for (std::size_t at = r->err.find("error:"); at != std::string::npos; at = r->err.find("error:", at + 1)) ++errors;
    EXPECT_EQ(errors, 1u) << r->err;
    EXPECT_EQ(r->err.find('\n', r->err.find("error:")), r->err.size() - 1) << r->err;
  }
  EXPECT_FALSE(fs::exists(models + "/x"));
}

// Trees, shrinkage, augmentation and group validation through the program: recorded in the model file.
TEST_F(TrainerProgram, LeversAreRecordedInTheModelFile) {
  const test::RunResult r = train("--pos " + test::quote(people) + " --neg " + test::quote(negatives) +
                                  " --name levers --rounds 4 --depth 2 --learning-rate 0.5 --augment mirror"
                                  " --histogram-subtraction --operating-tar 0.9");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("augmentation (mirror, seed 1): 60 more positives"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("calibration platt"), std::string::npos) << r.err;
  const BoostedModel model = BoostedModel::load("levers", models);
  EXPECT_EQ(model.format_version(), kModelFormatVersion);
  EXPECT_EQ(model.weak_classifiers().front().kind, WeakClassifier::Kind::Tree);
  // The default 5 folds, one per group here (3 groups of 30 frames): every original validated once, by a
  // model that never saw its group; augmented copies are trained on, never validated.
  EXPECT_NE(model.training().validation.source.find("3 folds of whole groups (3 groups"), std::string::npos)
      << model.training().validation.source;
  EXPECT_EQ(model.training().validation.positives, 60u);
  EXPECT_EQ(model.training().train_positives, 120u);
  bool recorded = false, subtraction = false;
  for (const auto& [key, value] : model.training().parameters) {
    recorded = recorded || (key == "depth" && value == "2");
    subtraction = subtraction || (key == "histogram_subtraction" && value == "on");
  }
  EXPECT_TRUE(recorded);
  EXPECT_TRUE(subtraction);
  // --operating-tar: recorded, and the model states the point, where its validation accepts >= 90 %.
  const auto& parameters = model.training().parameters;
  EXPECT_NE(std::find(parameters.begin(), parameters.end(), std::make_pair(std::string("operating_tar"), std::string("0.9"))),
            parameters.end());
  ASSERT_TRUE(model.operating_point());
  EXPECT_NE(model.operating_point()->rule.find("validation TAR >= 0.9 (TAR "), std::string::npos)
      << model.operating_point()->rule;
  EXPECT_NE(r.err.find("operating point P(person) >= "), std::string::npos) << r.err;
  // The warning for a weak model: given exactly when the validation FAR at the point (in its rule) is above 0.05.
  const std::string& rule = model.operating_point()->rule;
  const double far = std::stod(rule.substr(rule.find("FAR ") + 4));
  EXPECT_EQ(r.err.find("rdsf-train: warning: at its operating point the model accepts ") != std::string::npos,
            far > kWeakOperatingFar)
      << r.err;
  const test::RunResult inspect = train("--inspect " + test::quote(model.path()));
  EXPECT_NE(inspect.out.find("operating    P(person) >= "), std::string::npos) << inspect.out;
}

// --thesis sets the thesis's value of every row that has one, of the boosting rows and of the training-data
// rows (training_data_parameters(): no augmentation); an option given explicitly still wins.
TEST_F(TrainerProgram, ThesisPresetTurnsAugmentationOffUnlessItIsGiven) {
  const std::string sets = "--pos " + test::quote(people) + " --neg " + test::quote(negatives) + " --rounds 2 ";
  auto recorded = [this](const std::string& name, const std::string& key) {
    const BoostedModel model = BoostedModel::load(name, models);  // alive while its parameters are read
    for (const auto& [k, value] : model.training().parameters) {
      if (k == key) return value;
    }
    return std::string("(none)");
  };
  ASSERT_EQ(train(sets + "--name thesis --thesis").exit_code, 0);
  EXPECT_EQ(recorded("thesis", "augmentation"), "off");
  EXPECT_EQ(recorded("thesis", "depth"), "1");
  ASSERT_EQ(train(sets + "--name thesis-mirrored --thesis --augment mirror --group-frames 10").exit_code, 0);
  EXPECT_EQ(recorded("thesis-mirrored", "augmentation"), "mirror, seed 1");
  EXPECT_EQ(recorded("thesis-mirrored", "group_frames"), "10");
  ASSERT_EQ(train(sets + "--name defaults").exit_code, 0);
  EXPECT_EQ(recorded("defaults", "augmentation"), "mirror, seed 1");
  EXPECT_EQ(recorded("defaults", "group_frames"), "30");
  EXPECT_EQ(recorded("defaults", "group_by"), "recording-block");
}

// rdsf-train --init: a lab's own samples continue a model; the new model holds the old weak classifiers
// first and records where it came from; a model of other bins or another spec is refused before any work.
TEST_F(TrainerProgram, InitContinuesAModelOnNewSetsAndRefusesOneThatDoesNotFit) {
  const std::string sets = "--pos " + test::quote(people) + " --neg " + test::quote(negatives);
  ASSERT_EQ(train(sets + " --name base --rounds 3 --bins 32").exit_code, 0);
  const std::string more_people = dir / "more-people", more_negatives = dir / "more-negatives";
  make_set(more_people, 1, 60, 7);
  make_set(more_negatives, 0, 60, 8);
  const std::string more = "--pos " + test::quote(more_people) + " --neg " + test::quote(more_negatives);
  const test::RunResult r = train(more + " --name lab --init base --rounds 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("continuing base/v1"), std::string::npos) << r.err;
  const BoostedModel base = BoostedModel::load("base", models), lab = BoostedModel::load("lab", models);
  ASSERT_EQ(lab.weak_classifiers().size(), 5u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_TRUE(lab.weak_classifiers()[k] == base.weak_classifiers()[k]) << k;
  EXPECT_EQ(lab.bins().count, 32);
  bool recorded = false;
  for (const auto& [key, value] : lab.training().parameters) {
    recorded = recorded || (key == "init" && value.find("base/v1") == 0);
  }
  EXPECT_TRUE(recorded);

  // A feature pool (as the default memory budget draws for a large base) gets the init model's features
  // added, so its scores come from the rows; the model names the spec's features.
  const test::RunResult pooled = train(more + " --name lab5 --init base --rounds 2 --feature-pool 20");
  ASSERT_EQ(pooled.exit_code, 0) << pooled.err;
  EXPECT_NE(pooled.err.find("more that the --init model reads"), std::string::npos) << pooled.err;
  const BoostedModel lab5 = BoostedModel::load("lab5", models);
  ASSERT_EQ(lab5.weak_classifiers().size(), 5u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_TRUE(lab5.weak_classifiers()[k] == base.weak_classifiers()[k]) << k;

  test::RunResult bad = train(more + " --name lab2 --init base --bins 64");
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_NE(bad.err.find("differs from the --init model's 32"), std::string::npos) << bad.err;
  const std::string rect_people = dir / "rect-people", rect_negatives = dir / "rect-negatives";
  make_set(rect_people, 1, 20, 3, FeatureSpec::rect());
  make_set(rect_negatives, 0, 20, 4, FeatureSpec::rect());
  bad = train("--pos " + test::quote(rect_people) + " --neg " + test::quote(rect_negatives) +
              " --name lab3 --init base --feature-pool 0 --rounds 2");
  EXPECT_EQ(bad.exit_code, 1) << bad.err;
  EXPECT_NE(bad.err.find("--init model reads feature spec"), std::string::npos) << bad.err;
  bad = train(more + " --name lab4 --init nosuchmodel");
  EXPECT_EQ(bad.exit_code, 1) << bad.err;
  EXPECT_NE(bad.err.find("error: nosuchmodel: no such model file"), std::string::npos) << bad.err;
  EXPECT_EQ(bad.err.find("samples "), std::string::npos) << bad.err;  // refused before any sample was read
  for (const char* name : {"lab2", "lab3", "lab4"}) EXPECT_FALSE(std::filesystem::exists(std::filesystem::path(models) / name));
}

}  // namespace
}  // namespace rdsf
