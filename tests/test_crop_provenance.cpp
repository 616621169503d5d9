// Crop provenance: sample-set manifests and model files (format 3) record how crops were cut
// (window_box, window_scale); a model refuses crops cut differently and says which parameter differs;
// files that do not record it (older formats, imports) agree with any; the format-3 reference file loads.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "rdsf/candidates/crop_provenance.hpp"
#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/classifier/model_file.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_manifest.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/frame/depth_png.hpp"
#include "rdsf/pipeline/model_fit.hpp"
#include "support/depth_scenes.hpp"
#include "support/test_support.hpp"

namespace rdsf {
namespace {

std::string reference_path(const std::string& name) {
  return (std::filesystem::path(RDSF_SOURCE_DIR) / "tests" / "reference_models" / name).string();
}

CropProvenance cut(double window_scale) {
  CropProvenance crops;
  crops.window_scale = window_scale;
  return crops;
}

TEST(CropProvenance, MismatchNamesTheParameterAndBothValues) {
  EXPECT_EQ(crop_provenance_mismatch(cut(1.25), "a", cut(1.25), "b"), "");
  EXPECT_EQ(crop_provenance_mismatch(cut(1.25), "a", CropProvenance{}, "b"), "");  // unknown agrees with any
  EXPECT_EQ(crop_provenance_mismatch(CropProvenance{}, "a", cut(1.5), "b"), "");
  EXPECT_EQ(crop_provenance_mismatch(cut(1.25), "the model's", cut(1.1), "the detector's"),
            "window_scale 1.25 (the model's) differs from 1.1 (the detector's)");
  CropProvenance fitted = cut(1.25);
  fitted.window_box = "fitted";
  EXPECT_EQ(crop_provenance_mismatch(fitted, "a", cut(1.25), "b"), "window_box fitted (a) differs from strict (b)");
  CandidateParams params;
  EXPECT_EQ(crop_provenance(params), cut(1.25));  // the thesis's 25 % margin
  EXPECT_EQ(known_of(CropProvenance{}, cut(1.5)), cut(1.5));
}

TEST(CropProvenance, ManifestRecordsTheCutAndOldManifestsReadAsUnknown) {
  SampleSetManifest m;
  m.created = "2026-12-01T00:00:00Z";
  m.created_by = "test";
  const SampleSetManifest old = SampleSetManifest::parse(m.to_text(), "old/manifest.yml");
  EXPECT_FALSE(old.crops.known());
  EXPECT_EQ(m.to_text().find("crops"), std::string::npos);  // unknown: not written, as before
  m.crops = cut(1.3);
  const std::string text = m.to_text();
  EXPECT_NE(text.find("window_scale"), std::string::npos) << text;
  EXPECT_EQ(SampleSetManifest::parse(text, "new/manifest.yml").crops, cut(1.3));
  std::string bad = text;
  bad.replace(bad.find("window_scale: "), 14, "window_scale: -");
  EXPECT_NE(test::error_message([&] { SampleSetManifest::parse(bad, "bad/manifest.yml"); }).find("bad/manifest.yml: "),
            std::string::npos);
}

TEST(CropProvenance, WriterRefusesCropsCutDifferentlyFromTheSets) {
  const test::TempDir dir("rdsf-crops");
  const std::string set = (dir / "set");
  { SampleSetWriter w = SampleSetWriter::open_or_create(set, FeatureSpec{}, CameraModel::kinect_v1(), "test", cut(1.25)); }
  EXPECT_EQ(SampleSet::open_read(set).manifest().crops, cut(1.25));
  const std::string message =
      test::error_message([&] { SampleSetWriter::open_or_create(set, FeatureSpec{}, CameraModel::kinect_v1(), "test", cut(1.5)); });
  EXPECT_NE(message.find(set + ": "), std::string::npos) << message;
  EXPECT_NE(message.find("window_scale 1.25"), std::string::npos) << message;
  EXPECT_NE(message.find("1.5"), std::string::npos) << message;
  // Samples without crops (imports) do not say how crops were cut: they may join.
  EXPECT_NO_THROW(SampleSetWriter::open_or_create(set, FeatureSpec{}, CameraModel::kinect_v1(), "test"));
}

TEST(CropProvenance, FormatThreeReferenceLoadsWithItsCutAndScore) {
  const BoostedModel model = BoostedModel::load(reference_path("rdsf-model-v3-crops.yml"));
  EXPECT_EQ(model.format_version(), 3);
  EXPECT_EQ(model.name(), "reference-crops");
  EXPECT_EQ(model.training().crops, cut(1.25));
  cv::Mat1f row(1, 8128);
  for (int i = 0; i < 8128; ++i) row(0, i) = static_cast<float>((i * 37) % 101) / 100.0f;
  const double h = model.score(row[0]);
  EXPECT_NEAR(h, 0.41297738721671357, 1e-9);
  EXPECT_NEAR(model.probability(h), 0.76869090217820368, 1e-9);
  // Older formats have no record.
  EXPECT_FALSE(BoostedModel::load(reference_path("rdsf-model-v2-tree.yml")).training().crops.known());
}

TEST(CropProvenance, ModelFileRoundTripKeepsTheCut) {
  const test::TempDir dir("rdsf-crops-model");
  BoostedModel model = BoostedModel::load(reference_path("rdsf-model-v3-crops.yml"));
  model.training().crops = cut(1.4);
  const std::string path = dir / "m.yml";
  std::ofstream(path) << model_file_text(model);
  EXPECT_EQ(BoostedModel::load(path).training().crops, cut(1.4));
  model.training().crops = CropProvenance{};
  std::ofstream(path) << model_file_text(model);
  EXPECT_FALSE(BoostedModel::load(path).training().crops.known());
}

TEST(CropProvenance, ModelRefusesADetectorThatCutsOtherwise) {
  const BoostedModel model = BoostedModel::load(reference_path("rdsf-model-v3-crops.yml"));
  AnalyserParams detector;
  EXPECT_EQ(model_fit_problem(model, detector), "");
  detector.candidates.window_scale = 1.5;
  const std::string problem = model_fit_problem(model, detector);
  EXPECT_EQ(problem, "crops cut differently: window_scale 1.25 (the model's training crops) differs from 1.5 "
                     "(the detector's)");
  const std::string message = test::error_message([&] { check_model_fits(model, detector); });
  EXPECT_EQ(message.find(model.path() + ": crops cut differently"), 0u) << message;
  // No record: not checked.
  EXPECT_EQ(model_fit_problem(BoostedModel::load(reference_path("rdsf-model-v2-tree.yml")), detector), "");
  // The feature spec is checked first, in the same place.
  AnalyserParams rect;
  rect.features = FeatureSpec::parse("rdsf-rect");
  EXPECT_NE(model_fit_problem(model, rect).find("model feature spec"), std::string::npos);
}

// rdsf-detect runs the check: another --window-scale than the model's training crops is an error.
TEST(CropProvenance, DetectProgramSaysWhichParameterDiffers) {
  const test::TempDir dir("rdsf-crops-detect");
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {300, 100, 40, 360}, 2000);
  write_png_atomically(dir / "scene.depth.png", frame.depth_mm);
  const std::string base = test::quote(test::program("rdsf-detect")) + " --source " + test::quote(dir.path().string()) +
                           " --model " + test::quote(reference_path("rdsf-model-v3-crops.yml")) + " --force --out " +
                           test::quote(dir / "out.csv");
  EXPECT_EQ(test::run(base).exit_code, 0);
  const test::RunResult r = test::run(base + " --window-scale 1.5");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("window_scale 1.25 (the model's training crops) differs from 1.5"), std::string::npos) << r.err;
}

// A set of `count` plain crops (label 1: a tall block, 0: a low one), cut as `crops` says.
void write_set(const std::string& dir, int label, int count, const CropProvenance& crops) {
  SampleSetWriter writer = SampleSetWriter::open_or_create(dir, FeatureSpec{}, CameraModel{}, "test", crops);
  for (int i = 0; i < count; ++i) {
    SampleRecord r;
    r.label = label;
    r.origin = "test";
    r.source = "recording" + std::to_string(i % 3);
    r.frame = std::to_string(i);
    r.strict_box = cv::Rect(i, 0, 10, 20);
    r.window = r.strict_box;
    cv::Mat1w crop(128, 64, std::uint16_t{0});
    const int height = label == 1 ? 100 + i % 20 : 30 + i % 20;
    cv::rectangle(crop, cv::Rect(20 + i % 8, 128 - height, 24, height), 2000 + 10 * i, cv::FILLED);
    writer.append(r, crop);
  }
}

// rdsf-train records the sets' cut in the model and refuses sets cut differently.
TEST(CropProvenance, TrainerRecordsTheCutAndRefusesMixedSets) {
  const test::TempDir dir("rdsf-crops-train");
  write_set(dir / "pos", 1, 30, cut(1.25));
  write_set(dir / "neg", 0, 30, cut(1.25));
  write_set(dir / "neg-wide", 0, 30, cut(1.5));
  const std::string train = test::quote(test::program("rdsf-train")) + " --models-dir " + test::quote(dir / "models") +
                            " --rounds 2 --folds 0 --group-frames 0 --augment off --name toy --pos " + test::quote(dir / "pos");
  const test::RunResult ok = test::run(train + " --neg " + test::quote(dir / "neg"));
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(BoostedModel::load("toy", dir / "models").training().crops, cut(1.25));
  const test::RunResult mixed = test::run(train + " --neg " + test::quote(dir / "neg-wide"));
  EXPECT_EQ(mixed.exit_code, 1);
  EXPECT_NE(mixed.err.find(dir / "neg-wide" + ": crops cut differently: window_scale 1.5"), std::string::npos) << mixed.err;
}

}  // namespace
}  // namespace rdsf
