// Bad input on read and rdsf-samples --check / --repair: a crop truncated or replaced by another image, a
// manifest whose feature spec hash does not match, samples.tsv edited by hand with a duplicate id, a torn
// row, a crop without a row.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <opencv2/imgcodecs.hpp>

#include "rdsf/core/error.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_check.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "support/test_support.hpp"

using namespace rdsf;
namespace fs = std::filesystem;

namespace {

void make_set(const std::string& dir, int count) {
  SampleSetWriter w = SampleSetWriter::open_or_create(dir, FeatureSpec{}, CameraModel::kinect_v1(), "test");
  for (int i = 0; i < count; ++i) {
    SampleRecord r;
    r.label = i % 2;
    r.origin = "labeler";
    r.source = "toy";
    r.frame = std::to_string(i);
    r.strict_box = r.window = cv::Rect(i, 0, 10, 20);
    w.append(r, cv::Mat1w(128, 64, static_cast<std::uint16_t>(2000 + 11 * i)));
  }
}

std::string samples() { return test::quote(test::program("rdsf-samples")); }

}  // namespace

TEST(SampleSetCheck, TruncatedOrReplacedCropIsAOneLineErrorNamingSampleAndFile) {
  test::TempDir dir;
  const std::string set = dir / "set";
  make_set(set, 4);
  const std::string crop2 = set + "/crops/00000002.depth.png";
  const std::string bytes = test::file_text(crop2);
  std::ofstream(crop2, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  fs::copy_file(set + "/crops/00000001.depth.png", set + "/crops/00000003.depth.png",
                fs::copy_options::overwrite_existing);
  const SampleSet s = SampleSet::open_read(set);
  const std::string truncated = test::error_message([&] { s.depth_crop(1); });
  EXPECT_NE(truncated.find(crop2), std::string::npos) << truncated;
  EXPECT_NE(truncated.find("sample 2"), std::string::npos) << truncated;
  EXPECT_EQ(truncated.find('\n'), std::string::npos);
  const std::string replaced = test::error_message([&] { s.depth_crop(2); });
  EXPECT_NE(replaced.find("00000003.depth.png: sample 3: crop does not match its hash"), std::string::npos) << replaced;

  // --check lists both, exit 1; --repair retracts both after a backup; the set then checks clean.
  const test::RunResult check = test::run(samples() + " --set " + test::quote(set) + " --check");
  EXPECT_EQ(check.exit_code, 1);
  EXPECT_NE(check.out.find("crops/00000002.depth.png: sample 2: crop truncated or not a PNG"), std::string::npos)
      << check.out;
  EXPECT_NE(check.out.find("crops/00000003.depth.png: sample 3: crop does not match its hash"), std::string::npos)
      << check.out;
  const test::RunResult repair = test::run(samples() + " --set " + test::quote(set) + " --repair");
  ASSERT_EQ(repair.exit_code, 0) << repair.err;
  EXPECT_NE(repair.out.find("samples.tsv: copied to samples.tsv.bak-"), std::string::npos) << repair.out;
  EXPECT_NE(repair.out.find("sample 2: retracted"), std::string::npos) << repair.out;
  EXPECT_NE(repair.out.find("sample 3: retracted"), std::string::npos) << repair.out;
  EXPECT_EQ(test::run(samples() + " --check " + test::quote(set)).exit_code, 0);  // SET without --set too
  const SampleSet after = SampleSet::open_read(set);
  ASSERT_EQ(after.records().size(), 2u);  // samples 1 and 4, valid, kept
  EXPECT_EQ(after.records()[0].id, 1);
  EXPECT_EQ(after.records()[1].id, 4);
}

TEST(SampleSetCheck, DuplicateIdEditedByHandIsNamedAndRepaired) {
  test::TempDir dir;
  const std::string set = dir / "set";
  make_set(set, 3);
  {
    std::string tsv = test::file_text(set + "/samples.tsv");
    const std::size_t second = tsv.find('\n', tsv.find('\n') + 1) + 1;  // the row of sample 1
    const std::string row = tsv.substr(tsv.find('\n') + 1, second - tsv.find('\n') - 1);
    tsv += row;  // sample 1 again, at the end
    tsv += "4\t1";  // and a torn row
    std::ofstream(set + "/samples.tsv", std::ios::binary) << tsv;
  }
  std::ofstream(set + "/crops/00000009.depth.png") << "x";  // a crop without a row
  const std::string error = test::error_message([&] { SampleSet::open_read(set); });
  EXPECT_NE(error.find("samples.tsv:5"), std::string::npos) << error;
  EXPECT_NE(error.find("id 1"), std::string::npos) << error;
  const std::vector<SetProblem> problems = check_sample_set(set);
  ASSERT_EQ(problems.size(), 3u);
  const std::vector<std::string> changes = repair_sample_set(set);
  std::string all;
  for (const std::string& c : changes) all += c + "\n";
  EXPECT_NE(all.find("samples.tsv:5: row dropped"), std::string::npos) << all;
  EXPECT_NE(all.find("torn last row cut off"), std::string::npos) << all;
  EXPECT_NE(all.find("crops/00000009.depth.png: removed"), std::string::npos) << all;
  EXPECT_TRUE(check_sample_set(set).empty());
  EXPECT_EQ(SampleSet::open_read(set).records().size(), 3u);
  bool backup = false;
  for (const auto& e : fs::directory_iterator(set)) {
    if (e.path().filename().string().rfind("samples.tsv.bak-", 0) == 0) {
      backup = true;
      EXPECT_NE(test::file_text(e.path().string()).find("4\t1"), std::string::npos);  // the original, torn row and all
    }
  }
  EXPECT_TRUE(backup);
}

TEST(SampleSetCheck, ManifestWhoseHashDoesNotMatchIsReportedAndNothingChanged) {
  test::TempDir dir;
  const std::string set = dir / "set";
  make_set(set, 2);
  std::string manifest = test::file_text(set + "/manifest.yml");
  const std::size_t hash = manifest.find("hash:");
  ASSERT_NE(hash, std::string::npos);
  manifest.replace(manifest.find_first_of("0123456789abcdef", hash + 5), 4, "0000");
  std::ofstream(set + "/manifest.yml", std::ios::binary) << manifest;
  const std::string error = test::error_message([&] { SampleSet::open_read(set); });
  EXPECT_NE(error.find("manifest.yml: feature spec"), std::string::npos) << error;
  const test::RunResult check = test::run(samples() + " --set " + test::quote(set) + " --check");
  EXPECT_EQ(check.exit_code, 1);
  EXPECT_NE(check.out.find("cannot be repaired"), std::string::npos) << check.out;
  const test::RunResult repair = test::run(samples() + " --set " + test::quote(set) + " --repair");
  EXPECT_EQ(repair.exit_code, 1);
  EXPECT_NE(repair.err.find("nothing repaired"), std::string::npos) << repair.err;
}

TEST(SampleSetCheck, OpeningRetractsARowWhoseCropIsMissingAndSaysSo) {
  test::TempDir dir;
  const std::string set = dir / "set";
  make_set(set, 3);
  fs::remove(set + "/crops/00000002.depth.png");
  SampleSetWriter w = SampleSetWriter::open_existing(set);
  ASSERT_EQ(w.repairs().size(), 1u);
  EXPECT_EQ(w.repairs()[0], "sample 2: retracted (crop missing, crops/00000002.depth.png)");
  EXPECT_EQ(w.records().size(), 2u);
  EXPECT_NE(test::file_text(set + "/retracted.tsv").find("\tcrop missing\n"), std::string::npos);
}
