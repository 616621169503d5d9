// The thesis's text format: export and import round trip exactly; bad files are refused line by line.
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "rdsf/core/error.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/dataset/thesis_text.hpp"
#include "support/test_support.hpp"

using rdsf::SampleRecord;
using rdsf::SampleSet;
using rdsf::SampleSetWriter;

namespace {

cv::Mat1w random_crop(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> depth(400, 9000);
  cv::Mat1w crop(128, 64, std::uint16_t{0});
  for (int y = 5; y < 125; ++y) {
    for (int x = 8 + static_cast<int>(seed % 5); x < 56; ++x) crop(y, x) = static_cast<std::uint16_t>(depth(random));
  }
  return crop;
}

SampleSetWriter new_set(const std::string& dir) {
  return SampleSetWriter::open_or_create(dir, rdsf::FeatureSpec{}, rdsf::CameraModel::kinect_v1(), "test");
}

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const rdsf::Error& e) {
    return e.what();
  }
  return "(no error)";
}

/// A line "label v v v ..." with `count` values of `value`.
std::string line_of(const std::string& label, int count, const std::string& value = "0.5") {
  std::string line = label;
  for (int i = 0; i < count; ++i) line += " " + value;
  return line + "\n";
}

}  // namespace

TEST(ThesisText, ExportThenImportGivesTheSameFeatures) {
  rdsf::test::TempDir dir;
  {
    SampleSetWriter writer = new_set(dir / "crops");
    for (unsigned i = 0; i < 6; ++i) {
      SampleRecord r;
      r.label = i % 2 == 0 ? 1 : 0;
      r.origin = "labeler";
      r.source = "rec";
      r.frame = std::to_string(i);
      writer.append(r, random_crop(i));
    }
  }
  const rdsf::RdsfExtractor extractor;
  const SampleSet original = SampleSet::open_read(dir / "crops");
  EXPECT_EQ(rdsf::export_thesis_text(original, extractor, dir / "samples.txt", false), 6);
  // No silent overwrite.
  EXPECT_NE(error_of([&] { rdsf::export_thesis_text(original, extractor, dir / "samples.txt", false); })
                .find("already exists"),
            std::string::npos);

  SampleSetWriter writer = new_set(dir / "imported");
  const rdsf::ThesisImportResult result = rdsf::import_thesis_text(dir / "samples.txt", writer);
  EXPECT_EQ(result.lines, 6);
  EXPECT_EQ(result.imported, 6);
  writer.close();
  const SampleSet imported = SampleSet::open_read(dir / "imported");
  ASSERT_EQ(imported.records().size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    const SampleRecord& r = imported.records()[i];
    EXPECT_FALSE(r.has_crop);
    EXPECT_EQ(r.origin, "import");
    EXPECT_EQ(r.label, original.records()[i].label);
    EXPECT_EQ(r.frame, "line " + std::to_string(i + 1));
  }
  EXPECT_NE(error_of([&] { imported.depth_crop(0); }).find("has no crop"), std::string::npos);
  const cv::Mat1f a = original.features(extractor), b = imported.features(extractor);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);  // exactly: the text holds every float bit for bit

  // Exporting the imported set writes the same text; importing the same file again adds nothing.
  rdsf::export_thesis_text(imported, extractor, dir / "again.txt", false);
  std::ifstream first(dir / "samples.txt"), second(dir / "again.txt");
  std::stringstream first_text, second_text;
  first_text << first.rdbuf();
  second_text << second.rdbuf();
  EXPECT_EQ(first_text.str(), second_text.str());
  SampleSetWriter again = SampleSetWriter::open_existing(dir / "imported");
  const rdsf::ThesisImportResult repeat = rdsf::import_thesis_text(dir / "samples.txt", again);
  EXPECT_EQ(repeat.imported, 0);
  EXPECT_EQ(repeat.duplicates, 6);
}

TEST(ThesisText, ImportNamesTheFirstBadLineAndImportsNothing) {
  rdsf::test::TempDir dir;
  struct Case {
    std::string bad_line;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {line_of("1", 8127), ":3: 8127 feature values, expected 8128"},
      {line_of("1", 8129), ":3: more than 8128 feature values"},
      {line_of("2", 8128), ":3: label '2' must be 1 (person) or 0 (not)"},
      {line_of("0", 8128, "1.5"), ":3: value f1 = 1.5 is outside [0, 1]"},
      {line_of("0", 8128, "-0.1"), ":3: value f1 = -0.1 is outside [0, 1]"},
      {line_of("0", 8128, "0.3x"), ":3: value f1 '0.3x' is not a finite number"},
      {line_of("0", 8128, "nan"), ":3: value f1 'nan' is not a finite number"},
  };
  for (const Case& c : cases) {
    const std::string path = dir / "bad.txt";
    {
      std::ofstream out(path, std::ios::trunc);
      out << line_of("1", 8128) << "\n" << c.bad_line << line_of("0", 8128);
    }
    SampleSetWriter writer = new_set(dir / "set");
    const std::string message = error_of([&] { rdsf::import_thesis_text(path, writer); });
    EXPECT_NE(message.find(path + c.expected), std::string::npos) << message;
    EXPECT_TRUE(writer.records().empty());  // checked first, nothing imported
  }
  const std::string empty = dir / "empty.txt";
  { std::ofstream(empty) << "\n\n"; }
  SampleSetWriter writer = new_set(dir / "set");
  EXPECT_NE(error_of([&] { rdsf::import_thesis_text(empty, writer); }).find("holds no samples"), std::string::npos);
}

TEST(ThesisText, ImportedVectorsExistOnlyForTheirFeatureSpec) {
  rdsf::test::TempDir dir;
  const std::string path = dir / "one.txt";
  { std::ofstream(path) << line_of("1", 8128, "0.25"); }
  {
    SampleSetWriter writer = new_set(dir / "set");
    rdsf::import_thesis_text(path, writer);
  }
  const SampleSet set = SampleSet::open_read(dir / "set");
  const cv::Mat1f rows = set.features(rdsf::RdsfExtractor{});
  EXPECT_FLOAT_EQ(rows(0, 8127), 0.25f);
  rdsf::FeatureSpec other;
  other.bin_width_mm = 250;
  const std::string message = error_of([&] { set.features(rdsf::RdsfExtractor(other)); });
  EXPECT_NE(message.find("no stored feature vector"), std::string::npos) << message;
}
