// Model files: save/load round trip, version numbering without overwriting, NAME resolution, refusal of
// unknown format versions and foreign feature specs, and the reference files every release must load.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "rdsf/classifier/boost_training.hpp"
#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/classifier/model_file.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/classifier/operating_point.hpp"
#include "classifier_support/toy_data.hpp"
#include "rdsf/core/error.hpp"
#include "support/test_support.hpp"

namespace rdsf {
namespace {

namespace fs = std::filesystem;

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

BoostedModel small_model(int rounds = 6, const std::string& backend = "native") {
  const test::ToyData toy = test::noisy_toy(300, 99);
  BoostTrainingParams params;
  params.rounds = rounds;
  params.backend = backend;
  BoostedModel model = train_boosted_model(toy.rows, toy.labels, params);
  model.training().recipe = "ad hoc";
  model.training().sample_sets.push_back({"pos", "datasets/toy", "0123456789abcdef", 150, 140});
  return model;
}

TEST(ModelFile, SaveLoadGivesIdenticalScores) {
  const test::TempDir dir("rdsf-model-file");
  BoostedModel model = small_model();
  const std::string path = save_new_model_version(model, "toy", dir.path().string());
  EXPECT_EQ(path, (dir.path() / "toy" / "v1.yml").string());
  EXPECT_EQ(model.version(), 1);
  const BoostedModel loaded = BoostedModel::load(path);
  EXPECT_EQ(loaded.name(), "toy");
  EXPECT_EQ(loaded.version(), 1);
  EXPECT_EQ(loaded.path(), path);
  EXPECT_EQ(loaded.created(), model.created());
  EXPECT_EQ(loaded.feature_spec(), FeatureSpec{});
  EXPECT_EQ(loaded.weak_classifiers(), model.weak_classifiers());
  const test::ToyData probe = test::noisy_toy(50, 1234);
  const std::vector<double> a = model.score(probe.rows), b = loaded.score(probe.rows);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << i;  // bit-identical
  // The training record survives too, and writing the loaded model gives the same text.
  EXPECT_EQ(loaded.training().recipe, "ad hoc");
  ASSERT_EQ(loaded.training().sample_sets.size(), 1u);
  EXPECT_EQ(loaded.training().sample_sets[0].manifest_hash, "0123456789abcdef");
  EXPECT_EQ(loaded.training().validation.summary.auc, model.training().validation.summary.auc);
  ASSERT_FALSE(loaded.training().validation.rounds.empty());
  EXPECT_FALSE(loaded.training().validation.rounds.back().roc.empty());
  EXPECT_EQ(loaded.training().validation.rounds.back().roc.size(), model.training().validation.rounds.back().roc.size());
  EXPECT_EQ(model_file_text(loaded), model_file_text(model));
  EXPECT_THROW(loaded.score(probe.rows.colRange(0, 10).clone()), Error);
}

TEST(ModelFile, OpenCvModelRoundTripKeepsTheEmbeddedModel) {
  const test::TempDir dir("rdsf-model-file");
  BoostedModel model = small_model(3, "opencv");
  const std::string path = save_new_model_version(model, "cv", dir.path().string());
  const BoostedModel loaded = BoostedModel::load(path);
  EXPECT_FALSE(loaded.opencv_model_yaml().empty());
  EXPECT_EQ(loaded.weak_classifiers(), model.weak_classifiers());
  const test::ToyData probe = test::noisy_toy(30, 77);
  EXPECT_EQ(loaded.score(probe.rows), model.score(probe.rows));
  EXPECT_NE(test::file_text(path).find("opencv_model:"), std::string::npos);
}

TEST(ModelRegistry, VersionsCountUpAndNeverOverwrite) {
  const test::TempDir dir("rdsf-model-registry");
  const std::string models = dir.path().string();
  EXPECT_EQ(latest_model_version(models, "toy"), 0);
  BoostedModel first = small_model(2);
  const std::string v1 = save_new_model_version(first, "toy", models);
  const std::string v1_text = test::file_text(v1);
  BoostedModel second = small_model(3);
  const std::string v2 = save_new_model_version(second, "toy", models);
  EXPECT_EQ(fs::path(v2).filename(), "v2.yml");
  EXPECT_EQ(test::file_text(v1), v1_text);  // untouched
  // Somebody else's v3 is kept: the next save becomes v4.
  write_text(dir / "toy/v3.yml", "not mine\n");
  BoostedModel third = small_model(2);
  const std::string v4 = save_new_model_version(third, "toy", models);
  EXPECT_EQ(fs::path(v4).filename(), "v4.yml");
  EXPECT_EQ(test::file_text(dir / "toy/v3.yml"), "not mine\n");
  EXPECT_EQ(latest_model_version(models, "toy"), 4);
  // No temporary files are left behind.
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir.path() / "toy")) {
    EXPECT_EQ(entry.path().extension(), ".yml") << entry.path();
    ++files;
  }
  EXPECT_EQ(files, 4);
  EXPECT_THROW(save_new_model_version(third, "../escape", models), Error);
  EXPECT_THROW(save_new_model_version(third, "", models), Error);
  EXPECT_THROW(save_new_model_version(third, "recipes", models), Error);
}

TEST(ModelRegistry, NameResolvesToItsNewestVersion) {
  const test::TempDir dir("rdsf-model-registry");
  const std::string models = dir.path().string();
  BoostedModel a = small_model(2), b = small_model(4);
  save_new_model_version(a, "tree2", models);
  save_new_model_version(b, "tree2", models);
  EXPECT_EQ(BoostedModel::load("tree2", models).version(), 2);
  EXPECT_EQ(BoostedModel::load("tree2", models).weak_classifiers().size(), 4u);
  EXPECT_EQ(BoostedModel::load("tree2/v1", models).version(), 1);
  EXPECT_EQ(BoostedModel::load("tree2/v1.yml", models).version(), 1);
  EXPECT_EQ(BoostedModel::load((dir.path() / "tree2").string()).version(), 2);
  EXPECT_NE(test::error_message([&] { BoostedModel::load("tree3", models); }).find("no model versions under"),
            std::string::npos);
  EXPECT_NE(test::error_message([&] { BoostedModel::load("tree2/v9", models); }).find("no such model version"),
            std::string::npos);
}

// The operating point (operating_point.hpp): written only when the model states one, read back as written,
// the default 0.5 without it, and a probability outside (0, 1) refused naming the file and the key.
TEST(ModelFile, OperatingPointRoundTripsAndIsAbsentUnlessStated) {
  const test::TempDir dir("rdsf-model-file");
  BoostedModel plain = small_model(2);
  const std::string plain_path = save_new_model_version(plain, "plain", dir.path().string());
  EXPECT_EQ(test::file_text(plain_path).find("operating_point"), std::string::npos);
  EXPECT_FALSE(BoostedModel::load(plain_path).operating_point());
  EXPECT_EQ(BoostedModel::load(plain_path).operating_probability(), 0.5);

  BoostedModel stated = small_model(2);
  stated.set_operating_point(OperatingPoint{0.27, "the highest P on a 0.01 grid with validation TAR >= 0.8"});
  const std::string path = save_new_model_version(stated, "stated", dir.path().string());
  const BoostedModel loaded = BoostedModel::load(path);
  ASSERT_TRUE(loaded.operating_point());
  EXPECT_EQ(loaded.operating_probability(), 0.27);
  EXPECT_EQ(loaded.operating_point()->rule, "the highest P on a 0.01 grid with validation TAR >= 0.8");
  EXPECT_EQ(model_file_text(loaded), model_file_text(stated));

  const std::string bad = dir / "bad.yml";
  write_text(bad, replace_once(test::file_text(path), "probability: 2.7000000000000002e-01", "probability: 1.5"));
  const std::string message = test::error_message([&] { BoostedModel::load(bad); });
  EXPECT_NE(message.find(bad + ": 'operating_point.probability' must lie strictly between 0 and 1"), std::string::npos)
      << message;
}

// choose_operating_point: the highest P of the 0.01 grid at which at least the target share of the positives
// is accepted, with the TAR and FAR there in its rule; none when no grid point reaches the target.
TEST(OperatingPoint, IsTheHighestGridProbabilityReachingTheTargetTar) {
  // Uncalibrated (P = 1 / (1 + exp(-2 H))): positives at H 0.1, 0.2, ..., 1.0, negatives at -1, -0.5, 0.3.
  std::vector<double> scores;
  std::vector<int> labels;
  for (int k = 1; k <= 10; ++k) {
    scores.push_back(0.1 * k);
    labels.push_back(1);
  }
  for (const double h : {-1.0, -0.5, 0.3}) {
    scores.push_back(h);
    labels.push_back(0);
  }
  const ScoreCalibration none;
  const auto point = choose_operating_point(scores, labels, none, 0.8);
  ASSERT_TRUE(point);
  // 8 of 10 positives need H >= 0.3, P = 1 / (1 + exp(-0.6)) = 0.6457: the grid's 0.64 keeps them, 0.65 not.
  EXPECT_DOUBLE_EQ(point->probability, 0.64);
  EXPECT_NE(point->rule.find("TAR 0.800, FAR 0.3333"), std::string::npos) << point->rule;
  EXPECT_DOUBLE_EQ(point->validation_far, 1.0 / 3.0);  // what rdsf-train's warning reads (> kWeakOperatingFar)
  EXPECT_DOUBLE_EQ(choose_operating_point(scores, labels, none, 0.1)->probability, 0.88);  // H 1.0: P 0.8808
  // Every positive needs P >= 0.5498 (H 0.1): the grid's 0.54.
  EXPECT_DOUBLE_EQ(choose_operating_point(scores, labels, none, 1.0)->probability, 0.54);
  const std::vector<double> low{-3.0, -3.0};
  EXPECT_FALSE(choose_operating_point(low, {1, 0}, none, 1.0));  // P 0.0025 < 0.01
  EXPECT_THROW(choose_operating_point(scores, labels, none, 0.0), Error);
}

TEST(ModelFile, UnknownFormatVersionIsRefused) {
  const test::TempDir dir("rdsf-model-file");
  BoostedModel model = small_model(2);
  const std::string path = save_new_model_version(model, "toy", dir.path().string());
  const std::string bad = dir / "future.yml";
  write_text(bad, replace_once(test::file_text(path), "format_version: " + std::to_string(kModelFormatVersion), "format_version: 7"));
  const std::string message = test::error_message([&] { BoostedModel::load(bad); });
  EXPECT_NE(message.find(bad + ": model format version 7 is not known"), std::string::npos) << message;
  const std::string other = dir / "other.yml";
  write_text(other, replace_once(test::file_text(path), "format: rdsf-model", "format: something-else"));
  EXPECT_NE(test::error_message([&] { BoostedModel::load(other); }).find("not an rdsf model file"), std::string::npos);
  write_text(other, "]]] not yaml {{{\n");
  EXPECT_NE(test::error_message([&] { BoostedModel::load(other); }).find(other + ":"), std::string::npos);
}

TEST(ModelFile, ForeignFeatureSpecIsRefusedSayingWhichDiffers) {
  const test::TempDir dir("rdsf-model-file");
  // A model made for 16-pixel cells (32 cells, 496 features): a spec this build knows, so it loads...
  FeatureSpec coarse;
  coarse.cell_px = 16;
  WeakClassifier w;
  w.feature = 3;
  w.responses.assign(64, 0.25);
  BoostedModel model(coarse, BinScheme{}, {w});
  const std::string path = save_new_model_version(model, "coarse", dir.path().string());
  EXPECT_EQ(BoostedModel::load(path).feature_spec(), coarse);
  EXPECT_EQ(read_model_file(path, coarse).feature_spec(), coarse);
  // ... but a caller computing the thesis's features refuses it, naming both.
  const std::string message = test::error_message([&] { read_model_file(path, FeatureSpec{}); });
  EXPECT_NE(message.find("feature spec differs"), std::string::npos) << message;
  EXPECT_NE(message.find("cell=16"), std::string::npos) << message;
  EXPECT_NE(message.find("cell=8"), std::string::npos) << message;
  EXPECT_NE(message.find(coarse.hash()), std::string::npos) << message;
  // And a default model refused by a build computing something else.
  BoostedModel normal = small_model(2);
  const std::string normal_path = save_new_model_version(normal, "normal", dir.path().string());
  EXPECT_NE(test::error_message([&] { read_model_file(normal_path, coarse); }).find("this build computes"),
            std::string::npos);
  // A damaged spec (numbers and canonical text disagree) is named as such.
  const std::string damaged = dir / "damaged.yml";
  write_text(damaged, replace_once(test::file_text(normal_path), "cell_px: 8", "cell_px: 4"));
  EXPECT_NE(test::error_message([&] { BoostedModel::load(damaged); }).find("damaged"), std::string::npos);
  // A spec this build does not know is refused on one line.
  const std::string unknown = dir / "unknown.yml";
  write_text(unknown, replace_once(test::file_text(normal_path), "pairs=upper-row-major", "pairs=lower-column-major"));
  const std::string unknown_message = test::error_message([&] { BoostedModel::load(unknown); });
  EXPECT_NE(unknown_message.find("is not one this build knows"), std::string::npos) << unknown_message;
  EXPECT_EQ(unknown_message.find('\n'), std::string::npos);
}

TEST(ModelFile, RectFeatureSpecModelsRoundTrip) {
  const test::TempDir dir("rdsf-model-file");
  WeakClassifier w;
  w.feature = 120000;  // beyond the thesis's 8128
  w.responses.assign(64, -0.5);
  BoostedModel model(FeatureSpec::rect(), BinScheme{}, {w});
  const std::string path = save_new_model_version(model, "rect", dir.path().string());
  const std::string text = test::file_text(path);
  EXPECT_NE(text.find("name: rdsf-rect"), std::string::npos);
  EXPECT_NE(text.find("rect_stride_px: 8"), std::string::npos);
  const BoostedModel loaded = BoostedModel::load(path);
  EXPECT_EQ(loaded.feature_spec(), FeatureSpec::rect());
  EXPECT_EQ(loaded.weak_classifiers(), model.weak_classifiers());
  const std::string message = test::error_message([&] { read_model_file(path, FeatureSpec{}); });
  EXPECT_NE(message.find("rdsf-rect/1"), std::string::npos) << message;
  EXPECT_NE(message.find("rdsf/1"), std::string::npos) << message;
}

TEST(ModelFile, TruncatedWeakListIsRefused) {
  const test::TempDir dir("rdsf-model-file");
  BoostedModel model = small_model(2);
  const std::string path = save_new_model_version(model, "toy", dir.path().string());
  const std::string bad = dir / "cut.yml";
  write_text(bad, replace_once(test::file_text(path), "weak_count: 2", "weak_count: 3"));
  EXPECT_NE(test::error_message([&] { BoostedModel::load(bad); }).find("truncated"), std::string::npos);
}

// The fixed input of the reference files: value i = ((i * 37) % 101) / 100.
cv::Mat1f reference_input() {
  cv::Mat1f row(1, 8128);
  for (int i = 0; i < 8128; ++i) row(0, i) = static_cast<float>((i * 37) % 101) / 100.0f;
  return row;
}

std::string reference_path(const std::string& name) {
  return (fs::path(RDSF_SOURCE_DIR) / "tests" / "reference_models" / name).string();
}

// Format version 1 must load, forever, with these scores. Do not regenerate these files: add new ones for
// new format versions (see tests/reference_models/README.md).
TEST(ReferenceModels, FormatVersion1NativeLoadsWithKnownScores) {
  const BoostedModel model = BoostedModel::load(reference_path("rdsf-model-v1-native.yml"));
  EXPECT_EQ(model.name(), "reference-native");
  EXPECT_EQ(model.version(), 1);
  EXPECT_EQ(model.weak_classifiers().size(), 5u);
  EXPECT_EQ(model.training().backend, "native");
  ASSERT_EQ(model.training().validation.rounds.size(), 3u);  // rounds 2, 4 and the last, 5
  EXPECT_EQ(model.training().validation.rounds.back().round, 5);
  EXPECT_FALSE(model.training().validation.rounds.back().roc.empty());
  const cv::Mat1f input = reference_input();
  EXPECT_NEAR(model.score(input[0]), -1.2211271644717994, 1e-9);
}

// The file of the newest format, read and written again, is the same text to the byte: the reader keeps
// every entry (training record, validation figures, rounds) and the writer writes them as they were.
TEST(ReferenceModels, NewestFormatReadAndWrittenAgainIsTheSameText) {
  for (const char* name : {"rdsf-model-v3-crops.yml", "rdsf-model-v4-detection-options.yml"}) {
    const std::string path = reference_path(name);
    EXPECT_EQ(model_file_text(read_model_file(path)), test::file_text(path)) << name;
  }
}

// Format 4: the v3 file's model stating its detection options; the same scores, the options read back.
TEST(ReferenceModels, FormatVersion4StatesItsDetectionOptions) {
  const BoostedModel v3 = BoostedModel::load(reference_path("rdsf-model-v3-crops.yml"));
  const BoostedModel v4 = BoostedModel::load(reference_path("rdsf-model-v4-detection-options.yml"));
  EXPECT_EQ(v3.format_version(), 3);
  EXPECT_TRUE(v3.detection_options().empty());
  EXPECT_EQ(v4.format_version(), 4);
  const cv::Mat1f input = reference_input();
  EXPECT_EQ(v4.score(input[0]), v3.score(input[0]));
  EXPECT_NEAR(v4.score(input[0]), 0.41297738721671357, 1e-9);
  const RecordedParameters& stated = v4.detection_options();
  EXPECT_GE(stated.size(), 50u);
  EXPECT_NE(std::find(stated.begin(), stated.end(), std::make_pair(std::string("hole_gap"), std::string("20"))),
            stated.end());
  EXPECT_NE(std::find(stated.begin(), stated.end(), std::make_pair(std::string("k"), std::string("6"))), stated.end());
}

// A model stating no options is written as format 3, without the section; stating them, as format 4; a bad
// section is one line naming the file and the option.
TEST(ModelFile, DetectionOptionsMakeFormatFourAndBadOnesAreRefused) {
  const test::TempDir dir("rdsf-model-file");
  BoostedModel plain = small_model(2);
  EXPECT_EQ(model_file_text(plain).find("detection_options"), std::string::npos);
  EXPECT_NE(model_file_text(plain).find("format_version: 3\n"), std::string::npos);
  BoostedModel stated = small_model(2);
  stated.set_detection_options({{"hole_gap", "20"}, {"box", "strict"}});
  const std::string path = save_new_model_version(stated, "stated", dir.path().string());
  EXPECT_NE(test::file_text(path).find("format_version: 4\n"), std::string::npos);
  const BoostedModel loaded = BoostedModel::load(path);
  EXPECT_EQ(loaded.detection_options(), stated.detection_options());
  EXPECT_EQ(model_file_text(loaded), model_file_text(stated));

  const std::string text = test::file_text(path), bad = dir / "bad.yml";
  const auto refusal = [&](const std::string& from, const std::string& to) {
    write_text(bad, replace_once(text, from, to));
    return test::error_message([&] { BoostedModel::load(bad); });
  };
  EXPECT_NE(refusal("hole_gap: \"20\"", "hole_gap: \"-2\"").find(bad + ": 'detection_options': hole-gap must be at least 0"),
            std::string::npos);
  EXPECT_NE(refusal("hole_gap: \"20\"", "frobnicate: \"20\"").find(bad + ": 'detection_options': 'frobnicate' is not a known option"),
            std::string::npos);
  EXPECT_NE(refusal("hole_gap: \"20\"", "hole_gap: \"twenty\"").find("hole-gap must be a number, not 'twenty'"),
            std::string::npos);
  EXPECT_NE(refusal("box: strict", "box: round").find("box is fitted or strict, not 'round'"), std::string::npos);
  EXPECT_NE(refusal("detection_options:", "options_detected:").find(bad + ": missing 'detection_options'"),
            std::string::npos);
  write_text(bad, replace_once(text, "format_version: 4", "format_version: 3"));  // format 3 does not read them
  EXPECT_TRUE(BoostedModel::load(bad).detection_options().empty());
  EXPECT_NE(refusal("format_version: 4", "format_version: 5").find("this build reads versions 1 to 4"),
            std::string::npos);
}

TEST(ReferenceModels, FormatVersion1OpenCvLoadsWithKnownScores) {
  const BoostedModel model = BoostedModel::load(reference_path("rdsf-model-v1-opencv.yml"));
  EXPECT_EQ(model.name(), "reference-opencv");
  EXPECT_EQ(model.weak_classifiers().size(), 3u);
  EXPECT_EQ(model.weak_classifiers().front().kind, WeakClassifier::Kind::Stump);
  EXPECT_FALSE(model.opencv_model_yaml().empty());
  const cv::Mat1f input = reference_input();
  EXPECT_NEAR(model.score(input[0]), -0.4877636329465857, 1e-9);
}

// Format version 2: trees of look-up tables and a Platt calibration.
TEST(ReferenceModels, FormatVersion2TreeLoadsWithKnownScoreAndProbability) {
  const BoostedModel model = BoostedModel::load(reference_path("rdsf-model-v2-tree.yml"));
  EXPECT_EQ(model.name(), "reference-tree");
  EXPECT_EQ(model.format_version(), 2);
  ASSERT_EQ(model.weak_classifiers().size(), 4u);
  EXPECT_EQ(model.weak_classifiers().front().kind, WeakClassifier::Kind::Tree);
  EXPECT_EQ(model.weak_classifiers().front().nodes.size(), 3u);
  EXPECT_EQ(model.calibration().method, "platt");
  EXPECT_EQ(model.training().validation.by_probability.size(), 19u);
  const cv::Mat1f input = reference_input();
  const double h = model.score(input[0]);
  EXPECT_NEAR(h, -0.78159114377759153, 1e-9);
  EXPECT_NEAR(model.probability(h), 0.20575998946820628, 1e-9);
}

// Format 1 files have no calibration: P(person) is Real AdaBoost's reading of H as half the log-odds.
TEST(ReferenceModels, FormatVersion1ReadsAsUncalibrated) {
  const BoostedModel model = BoostedModel::load(reference_path("rdsf-model-v1-native.yml"));
  EXPECT_EQ(model.format_version(), 1);
  EXPECT_EQ(model.calibration().method, "none");
  EXPECT_NEAR(model.probability(-1.2211271644717994), 1.0 / (1.0 + std::exp(2 * 1.2211271644717994)), 1e-12);
}

}  // namespace
}  // namespace rdsf
