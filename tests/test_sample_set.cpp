// Sample sets: round trips, durability when the writer is killed mid-append, the lock, strict reading.
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <opencv2/imgcodecs.hpp>

#include "rdsf/core/error.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/dataset/sample_tsv.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using rdsf::SampleRecord;
using rdsf::SampleSet;
using rdsf::SampleSetWriter;

namespace {

/// A 64x128 masked depth crop: a "body" of random depths on zeros.
cv::Mat1w random_crop(unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> depth(500, 8000);
  cv::Mat1w crop(128, 64, std::uint16_t{0});
  for (int y = 10; y < 120; ++y) {
    for (int x = 12; x < 52; ++x) crop(y, x) = static_cast<std::uint16_t>(depth(random));
  }
  return crop;
}

SampleRecord miner_record(int frame, int label = 0) {
  SampleRecord r;
  r.label = label;
  r.origin = "miner";
  r.source = "recordings/lab";
  r.frame = "f" + std::to_string(frame);
  r.strict_box = cv::Rect(100 + frame, 50, 60, 120);
  r.window = cv::Rect(92 + frame, 35, 75, 150);
  r.layer_depth_mm = 2345.5;
  return r;
}

SampleSetWriter new_set(const std::string& dir) {
  return SampleSetWriter::open_or_create(dir, rdsf::FeatureSpec{}, rdsf::CameraModel::kinect_v1(), "test");
}

void append_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::app);
  out << text;
}

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const rdsf::Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(SampleSet, WriteAndReadBackEverything) {
  rdsf::test::TempDir dir;
  const std::string set_dir = dir / "set";
  cv::Mat3b colour(128, 64, cv::Vec3b(10, 200, 30));
  {
    SampleSetWriter writer = new_set(set_dir);
    SampleRecord first = miner_record(1);
    first.source = "odd\tname\\with\nescapes";
    first.model = "tree2/v3";
    first.score = -0.125;
    const SampleRecord stored = writer.append(first, random_crop(1), colour);
    EXPECT_EQ(stored.id, 1);
    EXPECT_TRUE(stored.has_colour);
    EXPECT_EQ(stored.crop_hash.size(), 16u);
    writer.append(miner_record(2, 1), random_crop(2));
    writer.append(miner_record(3), random_crop(3));
  }
  const SampleSet set = SampleSet::open_read(set_dir);
  ASSERT_EQ(set.records().size(), 3u);
  EXPECT_FALSE(set.torn_tail());
  EXPECT_EQ(set.count(0), 2u);
  EXPECT_EQ(set.count(1), 1u);
  EXPECT_EQ(set.manifest_hash().size(), 16u);
  EXPECT_EQ(set.feature_spec(), rdsf::FeatureSpec{});
  EXPECT_EQ(set.manifest().camera, rdsf::CameraModel::kinect_v1());
  const SampleRecord& r = set.records()[0];
  EXPECT_EQ(r.source, "odd\tname\\with\nescapes");
  EXPECT_EQ(r.frame, "f1");
  EXPECT_EQ(r.origin, "miner");
  EXPECT_EQ(r.strict_box, cv::Rect(101, 50, 60, 120));
  EXPECT_EQ(r.window, cv::Rect(93, 35, 75, 150));
  EXPECT_DOUBLE_EQ(r.layer_depth_mm, 2345.5);
  EXPECT_EQ(r.model, "tree2/v3");
  ASSERT_TRUE(r.score.has_value());
  EXPECT_DOUBLE_EQ(*r.score, -0.125);
  EXPECT_FALSE(set.records()[1].score.has_value());
  EXPECT_EQ(set.records()[1].label, 1);
  EXPECT_EQ(r.time.size(), 20u);  // 2026-11-22T05:30:00Z

  // Crops come back bit for bit, 64x128 16-bit; colour only where given.
  EXPECT_EQ(cv::norm(set.depth_crop(0), random_crop(1), cv::NORM_INF), 0.0);
  const cv::Mat raw = cv::imread(set.depth_crop_path(2), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(raw.type(), CV_16UC1);
  EXPECT_EQ(raw.size(), cv::Size(64, 128));
  EXPECT_EQ(cv::norm(set.colour_crop(0), colour, cv::NORM_INF), 0.0);
  EXPECT_TRUE(set.colour_crop(1).empty());

  // Features computed from the crops equal the extractor's on the original crops, in any order.
  const rdsf::RdsfExtractor extractor;
  const cv::Mat1f rows = set.features(extractor, {2, 0});
  ASSERT_EQ(rows.rows, 2);
  ASSERT_EQ(rows.cols, 8128);
  const std::vector<float> expected = extractor.compute(random_crop(3));
  EXPECT_EQ(0, std::memcmp(rows.ptr<float>(0), expected.data(), expected.size() * sizeof(float)));
  const std::vector<float> expected0 = extractor.compute(random_crop(1));
  EXPECT_EQ(0, std::memcmp(rows.ptr<float>(1), expected0.data(), expected0.size() * sizeof(float)));
  EXPECT_EQ(set.features(extractor).rows, 3);
}

TEST(SampleSet, ReopenedWriterContinuesIdsAndKnowsDuplicates) {
  rdsf::test::TempDir dir;
  const std::string set_dir = dir / "set";
  { new_set(set_dir).append(miner_record(1), random_crop(1)); }
  EXPECT_FALSE(fs::exists(set_dir + "/lock"));  // released on close
  SampleSetWriter writer = SampleSetWriter::open_existing(set_dir);
  EXPECT_FALSE(writer.took_over_stale_lock());
  EXPECT_TRUE(writer.is_duplicate(miner_record(1)));   // same place
  EXPECT_FALSE(writer.is_duplicate(miner_record(1, 1)));  // same place, other label
  SampleRecord moved = miner_record(9);
  EXPECT_FALSE(writer.is_duplicate(moved));
  moved.crop_hash = rdsf::depth_crop_hash(random_crop(1));
  EXPECT_TRUE(writer.is_duplicate(moved));  // same depth crop elsewhere
  EXPECT_EQ(writer.append(miner_record(2), random_crop(2)).id, 2);
  writer.close();
  EXPECT_EQ(SampleSet::open_read(set_dir).records().size(), 2u);
}

TEST(SampleSet, SecondWriterIsRefusedWithTheHolderNamed) {
  rdsf::test::TempDir dir;
  const std::string set_dir = dir / "set";
  SampleSetWriter first = new_set(set_dir);
  const std::string message = error_of([&] { SampleSetWriter::open_existing(set_dir); });
  EXPECT_NE(message.find(set_dir), std::string::npos) << message;
  EXPECT_NE(message.find("pid " + std::to_string(getpid())), std::string::npos) << message;
  EXPECT_NE(message.find("another program"), std::string::npos) << message;
  // Reading needs no lock.
  EXPECT_NO_THROW(SampleSet::open_read(set_dir));
}

TEST(SampleSet, LockOfAnotherProcessIsRefusedAndTakenOverAfterItWasKilled) {
  rdsf::test::TempDir dir;
  const std::string set_dir = dir / "set";
  { new_set(set_dir); }
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    SampleSetWriter writer = SampleSetWriter::open_existing(set_dir);
    const char byte = 'x';
    if (write(ready[1], &byte, 1) != 1) _exit(3);
    pause();
    _exit(0);
  }
  char byte = 0;
  ASSERT_EQ(read(ready[0], &byte, 1), 1);
  const std::string message = error_of([&] { SampleSetWriter::open_existing(set_dir); });
  EXPECT_NE(message.find("pid " + std::to_string(child)), std::string::npos) << message;
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  close(ready[0]);
  close(ready[1]);
  EXPECT_TRUE(fs::exists(set_dir + "/lock"));  // left behind by the killed writer
  SampleSetWriter writer = SampleSetWriter::open_existing(set_dir);
  EXPECT_TRUE(writer.took_over_stale_lock());
  EXPECT_NE(writer.stale_holder().find("pid " + std::to_string(child)), std::string::npos);
}

TEST(SampleSet, WriterKilledMidAppendLosesNoEarlierSample) {
  rdsf::test::TempDir dir;
  const std::string set_dir = dir / "set";
  { new_set(set_dir); }
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    SampleSetWriter writer = SampleSetWriter::open_existing(set_dir);
    for (unsigned i = 0;; ++i) writer.append(miner_record(static_cast<int>(i)), random_crop(i));
  }
  // Let it append a while, then kill it wherever it is.
  const std::string tsv = set_dir + "/samples.tsv";
  for (int wait = 0; wait < 2000; ++wait) {
    const std::string text = rdsf::test::file_text(tsv);
    if (std::count(text.begin(), text.end(), '\n') > 40) break;
    usleep(2000);
  }
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);

  const SampleSet set = SampleSet::open_read(set_dir);
  const std::string text = rdsf::test::file_text(tsv);
  const auto complete_rows = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) - 1;
  ASSERT_GE(complete_rows, 40u);
  ASSERT_EQ(set.records().size(), complete_rows);
  for (std::size_t i = 0; i < set.records().size(); ++i) {
    EXPECT_EQ(set.records()[i].id, static_cast<std::int64_t>(i) + 1);
    // Every sample whose row is there has its crop.
    EXPECT_EQ(cv::norm(set.depth_crop(i), random_crop(static_cast<unsigned>(i)), cv::NORM_INF), 0.0) << i;
  }
  // A new writer takes over and appends after the last complete sample.
  SampleSetWriter writer = SampleSetWriter::open_existing(set_dir);
  EXPECT_TRUE(writer.took_over_stale_lock());
  writer.append(miner_record(-1), random_crop(999));
  writer.close();
  EXPECT_EQ(SampleSet::open_read(set_dir).records().size(), complete_rows + 1);
}

TEST(SampleSet, TornLastRowIsIgnoredByReadersAndCutByTheNextWriter) {
  rdsf::test::TempDir dir;
  const std::string set_dir = dir / "set";
  {
    SampleSetWriter writer = new_set(set_dir);
    writer.append(miner_record(1), random_crop(1));
    writer.append(miner_record(2), random_crop(2));
  }
  // What a writer killed in the middle of sample 3 leaves: its crop and half its row.
  fs::copy_file(set_dir + "/crops/00000001.depth.png", set_dir + "/crops/00000003.depth.png");
  fs::copy_file(set_dir + "/crops/00000001.depth.png", set_dir + "/crops/00000003.rgb.png.tmp");
  append_text(set_dir + "/samples.tsv", "3\t0\tminer\trecordings/la");
  const SampleSet torn = SampleSet::open_read(set_dir);
  EXPECT_TRUE(torn.torn_tail());
  EXPECT_EQ(torn.records().size(), 2u);

  SampleSetWriter writer = SampleSetWriter::open_existing(set_dir);
  EXPECT_TRUE(writer.recovered_torn_row());
  EXPECT_FALSE(fs::exists(set_dir + "/crops/00000003.depth.png"));  // crop without row removed
  EXPECT_FALSE(fs::exists(set_dir + "/crops/00000003.rgb.png.tmp"));
  EXPECT_EQ(writer.append(miner_record(3), random_crop(3)).id, 3);
  writer.close();
  const SampleSet set = SampleSet::open_read(set_dir);
  EXPECT_FALSE(set.torn_tail());
  ASSERT_EQ(set.records().size(), 3u);
  EXPECT_EQ(set.records()[2].frame, "f3");
}

TEST(SampleSet, BadRowIsNamedByFileAndLine) {
  rdsf::test::TempDir dir;
  const std::string set_dir = dir / "set";
  {
    SampleSetWriter writer = new_set(set_dir);
    writer.append(miner_record(1), random_crop(1));
    writer.append(miner_record(2), random_crop(2));
  }
  const std::string tsv = set_dir + "/samples.tsv";
  std::string text = rdsf::test::file_text(tsv);
  // Row 2 (file line 3): a label that is not 0 or 1.
  const std::size_t line3 = text.find('\n', text.find('\n') + 1) + 1;
  const std::size_t label = text.find('\t', line3) + 1;
  text[label] = '7';
  { std::ofstream(tsv, std::ios::binary | std::ios::trunc) << text; }
  std::string message = error_of([&] { SampleSet::open_read(set_dir); });
  EXPECT_NE(message.find(tsv + ":3: column label"), std::string::npos) << message;
  // A row with a missing column.
  text[label] = '0';
  text.insert(line3, "9\t0\n");
  { std::ofstream(tsv, std::ios::binary | std::ios::trunc) << text; }
  message = error_of([&] { SampleSet::open_read(set_dir); });
  EXPECT_NE(message.find(tsv + ":3: 2 tab-separated columns, expected 20"), std::string::npos) << message;
  // The writer refuses a damaged set instead of appending to it.
  message = error_of([&] { SampleSetWriter::open_existing(set_dir); });
  EXPECT_NE(message.find(tsv + ":3:"), std::string::npos) << message;
}

TEST(SampleSet, RefusesWrongFoldersSpecsAndManifests) {
  rdsf::test::TempDir dir;
  // A folder with other files is not turned into a set.
  fs::create_directories(dir / "photos");
  { std::ofstream(dir / "photos/holiday.jpg") << "x"; }
  std::string message = error_of([&] { new_set(dir / "photos"); });
  EXPECT_NE(message.find("not a sample set"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(dir / "photos/manifest.yml"));
  // Another feature spec.
  { new_set(dir / "set"); }
  rdsf::FeatureSpec other;
  other.bin_width_mm = 250;
  message = error_of([&] {
    SampleSetWriter::open_or_create(dir / "set", other, rdsf::CameraModel::kinect_v1(), "test");
  });
  EXPECT_NE(message.find(rdsf::FeatureSpec{}.hash()), std::string::npos) << message;
  EXPECT_NE(message.find(other.hash()), std::string::npos) << message;
  // A manifest of an unknown version.
  const std::string manifest = dir / "set/manifest.yml";
  std::string text = rdsf::test::file_text(manifest);
  text.replace(text.find("format_version: 1"), 17, "format_version: 7");
  { std::ofstream(manifest, std::ios::trunc) << text; }
  message = error_of([&] { SampleSet::open_read(dir / "set"); });
  EXPECT_NE(message.find(manifest + ": format_version 7"), std::string::npos) << message;
  // No set at all.
  message = error_of([&] { SampleSet::open_read(dir / "nothing"); });
  EXPECT_NE(message.find("nothing"), std::string::npos) << message;
}

TEST(SampleSet, ManifestHashIsStableAndDependsOnTheContents) {
  rdsf::test::TempDir dir;
  { new_set(dir / "a"); }
  const SampleSet a = SampleSet::open_read(dir / "a");
  EXPECT_EQ(a.manifest_hash(), SampleSet::open_read(dir / "a").manifest_hash());
  const std::string manifest = dir / "a/manifest.yml";
  std::string text = rdsf::test::file_text(manifest);
  text.replace(text.find("created_by: test"), 16, "created_by: tost");
  { std::ofstream(manifest, std::ios::trunc) << text; }
  EXPECT_NE(a.manifest_hash(), SampleSet::open_read(dir / "a").manifest_hash());
}

TEST(SampleSet, RetractedSamplesAreLeftOutButNotErased) {
  rdsf::test::TempDir dir;
  const std::string set_dir = dir / "set";
  {
    SampleSetWriter writer = new_set(set_dir);
    for (int i = 1; i <= 3; ++i) writer.append(miner_record(i, 1), random_crop(static_cast<unsigned>(i)));
    writer.retract(3);  // the labeler's undo, twice
    writer.retract(2);
    EXPECT_EQ(writer.records().size(), 1u);
    EXPECT_FALSE(writer.is_duplicate(miner_record(2, 1)));  // may be answered again
    EXPECT_NE(error_of([&] { writer.retract(2); }).find("no such sample"), std::string::npos);
    EXPECT_NE(error_of([&] { writer.retract(42); }).find("cannot retract sample 42"), std::string::npos);
    EXPECT_EQ(writer.append(miner_record(2, 1), random_crop(2)).id, 4);  // ids are never reused
  }
  append_text(set_dir + "/retracted.tsv", "1\t2026-");  // torn retraction: not taken
  const SampleSet set = SampleSet::open_read(set_dir);
  ASSERT_EQ(set.records().size(), 2u);
  EXPECT_EQ(set.records()[0].id, 1);
  EXPECT_EQ(set.records()[1].id, 4);
  EXPECT_EQ(set.retracted_count(), 2u);
  EXPECT_TRUE(fs::exists(set_dir + "/crops/00000003.depth.png"));  // kept for inspection
  SampleSetWriter writer = SampleSetWriter::open_existing(set_dir);
  EXPECT_EQ(writer.records().size(), 2u);
  EXPECT_FALSE(writer.is_duplicate(miner_record(3, 1)));
  writer.retract(1);
  writer.close();
  EXPECT_EQ(SampleSet::open_read(set_dir).records().size(), 1u);
}
