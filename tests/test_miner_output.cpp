// What a mining run leaves (issue 17's faster miner must not change it): the rows and the crops' pixels of the
// real people-free frames are those main gave before the direct PNG encoder and the group commit
// (ae93907); the crops' bytes are libdeflate's (kSampleCropPng), pinned so that an encoder change shows,
// and the zlib path still gives main's bytes; flushing in groups of any size or on any number of threads
// leaves the same bytes.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "rdsf/core/stable_hash.hpp"
#include "rdsf/dataset/negative_miner.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;

namespace {

/// "WxH:type:" and the decoded pixels of PNG bytes, row by row, 16-bit samples little-endian.
std::string pixels_of(const std::string& png) {
  const cv::Mat image =
      cv::imdecode(cv::Mat(1, static_cast<int>(png.size()), CV_8U, const_cast<char*>(png.data())), cv::IMREAD_UNCHANGED);
  EXPECT_FALSE(image.empty());
  std::string out = std::to_string(image.cols) + "x" + std::to_string(image.rows) + ":" + std::to_string(image.type()) + ":";
  const std::size_t row_bytes = static_cast<std::size_t>(image.cols) * image.elemSize();
  for (int y = 0; y < image.rows; ++y) {
    const unsigned char* row = image.ptr(y);
    if (image.depth() == CV_8U) {
      out.append(reinterpret_cast<const char*>(row), row_bytes);
      continue;
    }
    const auto* samples = reinterpret_cast<const std::uint16_t*>(row);
    for (std::size_t i = 0; i < row_bytes / 2; ++i) {
      out += static_cast<char>(samples[i] & 0xff);
      out += static_cast<char>(samples[i] >> 8);
    }
  }
  return out;
}

/// FNV-1a 64 over every row of samples.tsv without its source (4th) and time (17th) columns, each followed by
/// the row's depth and colour crops: `hash` with the crops' file bytes, `pixels` with their decoded pixels
/// (pixels_of) instead. What a set holds, wherever and whenever it was mined.
struct SetDigest {
  std::string hash;
  std::string pixels;
  int rows = 0;
};

SetDigest digest_of(const std::string& dir) {
  std::ifstream in(fs::path(dir) / "samples.tsv");
  std::string line;
  std::getline(in, line);  // header
  std::uint64_t h = 0xcbf29ce484222325ULL, p = h;
  SetDigest digest;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> fields;
    std::stringstream row(line);
    std::string field;
    while (std::getline(row, field, '\t')) fields.push_back(field);
    if (line.back() == '\t') fields.emplace_back();
    EXPECT_EQ(fields.size(), 20u) << line;
    if (fields.size() != 20u) return digest;
    std::string kept;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (i == 3 || i == 16) continue;
      if (!kept.empty()) kept += '\t';
      kept += fields[i];
    }
    h = rdsf::fnv1a64(kept + "\n", h);
    p = rdsf::fnv1a64(kept + "\n", p);
    const std::string stem = rdsf::crop_stem(std::stoll(fields[0]));
    for (const char* kind : {".depth.png", ".rgb.png"}) {
      const fs::path crop = fs::path(dir) / (stem + kind);
      if (!fs::exists(crop)) continue;
      const std::string bytes = rdsf::test::file_text(crop);
      h = rdsf::fnv1a64(bytes, h);
      p = rdsf::fnv1a64(pixels_of(bytes), p);
    }
    ++digest.rows;
  }
  digest.hash = rdsf::to_hex16(h);
  digest.pixels = rdsf::to_hex16(p);
  return digest;
}

SetDigest mine_into(const std::string& dir, const std::string& source, int threads, int sync_every,
                    bool join_narrow_passing = rdsf::CandidateParams{}.join.narrow_passing,
                    const rdsf::PngEncodeOptions& crop_png = rdsf::kSampleCropPng,
                    double border_height_cm = rdsf::CandidateParams{}.border.height_cm) {
  rdsf::SampleSetWriter writer =
      rdsf::SampleSetWriter::open_or_create(dir, rdsf::FeatureSpec{}, rdsf::CameraModel::kinect_v1(), "test");
  rdsf::MineParams params;
  params.sources = {source};
  params.threads = threads;
  params.sync_every_frames = sync_every;
  params.analyser.candidates.join.narrow_passing = join_narrow_passing;
  params.analyser.candidates.border.height_cm = border_height_cm;
  params.crop_png = crop_png;
  std::vector<std::int64_t> reported;
  rdsf::mine_negatives(params, writer, [&](const rdsf::MineStats& s) {
    reported.push_back(s.frames);
    EXPECT_EQ(writer.unsynced_rows(), 0u) << "frames are reported once their rows are flushed";
  });
  EXPECT_FALSE(reported.empty());
  for (std::size_t i = 1; i < reported.size(); ++i) {
    EXPECT_LE(reported[i] - reported[i - 1], sync_every) << "a group holds at most sync_every frames";
  }
  writer.close();
  return digest_of(dir);
}

}  // namespace

TEST(MinerOutput, RealFramesGiveTheRowsAndPixelsOfBeforeTheFasterMiner) {
  RDSF_REQUIRE_REALDATA();
  rdsf::test::TempDir dir{"rdsf-miner-output"};
  // rdsf-mine --source ../shared/realdata/empty on main at ae93907 (cv::imencode crops, a flush per frame),
  // whose candidates are today's with join.narrow_passing off (issue 14 removed one of them since) and
  // without the border rule (off by default; on, it adds 4: BorderCutParams): its rows and crop pixels;
  // the crop bytes are libdeflate's since issue 17.
  const std::string empty = (rdsf::test::realdata_dir() / "empty").string();
  const SetDigest mined = mine_into(dir / "set", empty, 2, 16, /*join_narrow_passing=*/false, rdsf::kSampleCropPng,
                                    /*border_height_cm=*/0);
  EXPECT_EQ(mined.rows, 50);
  EXPECT_EQ(mined.pixels, "811c35eb9597e00a");
  EXPECT_EQ(mined.hash, "1c1e2a0ee70a55bb");
  // The zlib path still gives main's bytes at ae93907, and so the pixels pinned above are main's.
  const SetDigest zlib =
      mine_into(dir / "zlib", empty, 2, 16, /*join_narrow_passing=*/false, rdsf::PngEncodeOptions{1}, 0);
  EXPECT_EQ(zlib.rows, 50);
  EXPECT_EQ(zlib.hash, "488e366968cde91b");
  EXPECT_EQ(zlib.pixels, mined.pixels);
}

TEST(MinerOutput, GroupSizeAndThreadsLeaveTheSameBytes) {
  rdsf::test::TempDir dir{"rdsf-miner-groups"};
  const rdsf::test::RunResult r = rdsf::test::run(rdsf::test::quote(rdsf::test::program("rdsf-synth")) + " --out " +
                                                  rdsf::test::quote(dir / "empty") + " --frames 7 --empty --seed 11");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const SetDigest reference = mine_into(dir / "one", dir / "empty", 1, 1);
  EXPECT_GT(reference.rows, 7);
  EXPECT_EQ(mine_into(dir / "three", dir / "empty", 2, 3).hash, reference.hash);
  EXPECT_EQ(mine_into(dir / "all", dir / "empty", 2, 16).hash, reference.hash);
}

TEST(MinerOutput, AGroupNeverHoldsMoreRowsThanOpeningChecks) {
  rdsf::test::TempDir dir{"rdsf-writer-batch"};
  rdsf::SampleSetWriter writer =
      rdsf::SampleSetWriter::open_or_create(dir / "set", rdsf::FeatureSpec{}, rdsf::CameraModel::kinect_v1(), "test");
  const cv::Mat1w crop(128, 64, std::uint16_t{2000});
  std::size_t most = 0;
  for (int i = 0; i < 150; ++i) {
    rdsf::SampleRecord record;
    record.source = "toy";
    record.frame = std::to_string(i);
    cv::Mat1w mine = crop.clone();
    mine(0, 0) = static_cast<std::uint16_t>(i);
    writer.append_encoded(record, rdsf::EncodedCrop::encode(mine), /*sync=*/false);
    most = std::max(most, writer.unsynced_rows());
  }
  EXPECT_EQ(most, rdsf::SampleSetWriter::kMaxUnsyncedRows);
  writer.sync();
  EXPECT_EQ(writer.unsynced_rows(), 0u);
}

TEST(MinerOutput, SyncEveryBelowOneIsAUsageError) {
  rdsf::test::TempDir dir{"rdsf-miner-sync-every"};
  const rdsf::test::RunResult r = rdsf::test::run(rdsf::test::quote(rdsf::test::program("rdsf-mine")) +
                                                  " --source " + rdsf::test::quote(dir / "none") + " --out " +
                                                  rdsf::test::quote(dir / "set") + " --sync-every 0");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("must be at least 1"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "set"));
}
