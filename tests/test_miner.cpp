// rdsf-mine and the negative miner: negatives from people-free frames, resume without duplicates, shards
// that merge into the unsharded result, the lock, hard-negative mode.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <tuple>

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/dataset/negative_miner.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using rdsf::SampleSet;
using rdsf::test::quote;
using rdsf::test::run;

namespace {

std::string empty_frames() { return (rdsf::test::realdata_dir() / "empty").string(); }

std::string mine(const std::string& arguments) { return quote(rdsf::test::program("rdsf-mine")) + " " + arguments; }

/// What identifies a sample, ids and times aside.
using Key = std::tuple<int, std::string, std::string, int, int, int, int, int, int, int, int, std::string>;

std::vector<Key> keys_of(const std::string& dir) {
  std::vector<Key> keys;
  const SampleSet set = SampleSet::open_read(dir);
  for (const rdsf::SampleRecord& r : set.records()) {
    keys.emplace_back(r.label, r.source, r.frame, r.strict_box.x, r.strict_box.y, r.strict_box.width,
                      r.strict_box.height, r.window.x, r.window.y, r.window.width, r.window.height, r.crop_hash);
  }
  return keys;
}

std::vector<Key> sorted(std::vector<Key> keys) {
  std::sort(keys.begin(), keys.end());
  return keys;
}

rdsf::MineParams params_for(const std::string& source) {
  rdsf::MineParams p;
  p.sources = {source};
  return p;
}

rdsf::SampleSetWriter new_set(const std::string& dir) {
  return rdsf::SampleSetWriter::open_or_create(dir, rdsf::FeatureSpec{}, rdsf::CameraModel::kinect_v1(), "test");
}

}  // namespace

TEST(Miner, EmptyFramesGiveNegativesWhoseCropsAndFeaturesAreTrue) {
  RDSF_REQUIRE_REALDATA();
  rdsf::test::TempDir dir;
  const std::string set_dir = dir / "negatives";
  const auto result = run(mine("--source " + quote(empty_frames()) + " --out " + quote(set_dir)));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("candidates per frame"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("duplicates skipped 0"), std::string::npos) << result.err;

  const SampleSet set = SampleSet::open_read(set_dir);
  ASSERT_GT(set.records().size(), 9u);
  EXPECT_EQ(set.count(0), set.records().size());
  EXPECT_NE(result.err.find("kept " + std::to_string(set.records().size())), std::string::npos) << result.err;

  // Recompute every frame's candidates and features with the frame analyser.
  const rdsf::FrameAnalyser analyser;
  std::map<std::tuple<std::string, int, int, int, int>, std::vector<float>> expected;
  auto source = rdsf::open_frame_source(empty_frames());
  rdsf::DepthFrame frame;
  while (source->next(frame)) {
    const rdsf::FrameAnalysis analysis = analyser.analyse(frame);
    for (std::size_t i = 0; i < analysis.candidates.size(); ++i) {
      const cv::Rect& b = analysis.candidates[i].strict_box;
      const float* row = analysis.features.ptr<float>(static_cast<int>(i));
      expected[{frame.name, b.x, b.y, b.width, b.height}] = std::vector<float>(row, row + analysis.features.cols);
    }
  }
  EXPECT_EQ(expected.size(), set.records().size());
  const cv::Mat1f rows = set.features(analyser.extractor());
  for (std::size_t i = 0; i < set.records().size(); ++i) {
    const rdsf::SampleRecord& r = set.records()[i];
    EXPECT_EQ(r.origin, "miner");
    // The source names the recording with links resolved (sample_source.hpp), wherever ../shared is linked from.
    EXPECT_EQ(r.source, std::filesystem::canonical(empty_frames()).string());
    EXPECT_TRUE(r.has_crop);
    const cv::Mat crop = cv::imread(set.depth_crop_path(i), cv::IMREAD_UNCHANGED);
    EXPECT_EQ(crop.type(), CV_16UC1) << set.depth_crop_path(i);
    EXPECT_EQ(crop.size(), cv::Size(64, 128)) << set.depth_crop_path(i);
    const auto found = expected.find({r.frame, r.strict_box.x, r.strict_box.y, r.strict_box.width,
                                      r.strict_box.height});
    ASSERT_NE(found, expected.end()) << r.frame;
    EXPECT_EQ(0, std::memcmp(rows.ptr<float>(static_cast<int>(i)), found->second.data(),
                             found->second.size() * sizeof(float)))
        << "sample " << r.id;
  }
}

TEST(Miner, ResumingAfterAnInterruptedRunAddsNoDuplicates) {
  RDSF_REQUIRE_REALDATA();
  rdsf::test::TempDir dir;
  const std::string whole = dir / "whole", resumed = dir / "resumed";
  ASSERT_EQ(run(mine("--source " + quote(empty_frames()) + " --out " + quote(whole))).exit_code, 0);
  // An interrupted run: four frames mined, then killed mid-append (torn row, stale lock left behind).
  ASSERT_EQ(run(mine("--source " + quote(empty_frames()) + " --out " + quote(resumed) + " --max-frames 4")).exit_code,
            0);
  const std::size_t partial = SampleSet::open_read(resumed).records().size();
  ASSERT_GT(partial, 0u);
  { std::ofstream(resumed + "/samples.tsv", std::ios::app) << "99\t0\tminer\t/some/wh"; }
  { std::ofstream(resumed + "/lock") << "pid 999999 on host gone\n"; }

  const auto again = run(mine("--source " + quote(empty_frames()) + " --out " + quote(resumed)));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("took over the lock"), std::string::npos) << again.err;
  EXPECT_NE(again.err.find("cut off a sample row torn"), std::string::npos) << again.err;
  EXPECT_NE(again.err.find("duplicates skipped " + std::to_string(partial)), std::string::npos) << again.err;
  EXPECT_EQ(keys_of(resumed), keys_of(whole));

  // A third run finds everything there already.
  const auto third = run(mine("--source " + quote(empty_frames()) + " --out " + quote(resumed)));
  ASSERT_EQ(third.exit_code, 0) << third.err;
  EXPECT_NE(third.err.find("kept 0,"), std::string::npos) << third.err;
  EXPECT_EQ(keys_of(resumed), keys_of(whole));
}

TEST(Miner, ShardsMergedEqualAnUnshardedRun) {
  RDSF_REQUIRE_REALDATA();
  rdsf::test::TempDir dir;
  const std::string whole = dir / "whole";
  ASSERT_EQ(run(mine("--source " + quote(empty_frames()) + " --out " + quote(whole))).exit_code, 0);
  std::string shards;
  std::size_t shard_total = 0;
  for (int i = 1; i <= 3; ++i) {
    const std::string shard = dir / ("shard" + std::to_string(i));
    const auto result =
        run(mine("--source " + quote(empty_frames()) + " --out " + quote(shard) + " --shard " + std::to_string(i) + "/3"));
    ASSERT_EQ(result.exit_code, 0) << result.err;
    shard_total += SampleSet::open_read(shard).records().size();
    shards += " " + quote(shard);
  }
  const std::string merged = dir / "merged";
  const auto result = run(mine("--merge" + shards + " --out " + quote(merged)));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("added " + std::to_string(shard_total)), std::string::npos) << result.err;
  EXPECT_EQ(sorted(keys_of(merged)), sorted(keys_of(whole)));
  // Merged crops are the shards' crops.
  const SampleSet merged_set = SampleSet::open_read(merged);
  EXPECT_EQ(merged_set.features(rdsf::RdsfExtractor{}).rows, static_cast<int>(shard_total));

  // Merging again adds nothing; a set of another feature spec is refused.
  const auto repeat = run(mine("--merge" + shards + " --out " + quote(merged)));
  EXPECT_NE(repeat.err.find("added 0, duplicates skipped " + std::to_string(shard_total)), std::string::npos)
      << repeat.err;
  rdsf::FeatureSpec other;
  other.bin_width_mm = 250;
  { rdsf::SampleSetWriter::open_or_create(dir / "other", other, rdsf::CameraModel::kinect_v1(), "test"); }
  const auto refused = run(mine("--merge" + shards + " " + quote(dir / "other") + " --out " + quote(merged)));
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("feature spec " + other.hash()), std::string::npos) << refused.err;
  EXPECT_EQ(SampleSet::open_read(merged).records().size(), shard_total);

  // --merge with --source is a usage error, checked with the merge's other options, before anything is read.
  const auto both = run(mine("--source " + quote(empty_frames()) + " --merge" + shards + " --out " + quote(merged)));
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("give either --source or --merge, not both"), std::string::npos) << both.err;
  EXPECT_EQ(SampleSet::open_read(merged).records().size(), shard_total);
}

TEST(Miner, RefusesASetAnotherWriterHoldsAndBadShards) {
  RDSF_REQUIRE_REALDATA();
  rdsf::test::TempDir dir;
  const std::string set_dir = dir / "set";
  {
    rdsf::SampleSetWriter writer = new_set(set_dir);
    const auto locked = run(mine("--source " + quote(empty_frames()) + " --out " + quote(set_dir)));
    EXPECT_EQ(locked.exit_code, 1);
    EXPECT_NE(locked.err.find("pid " + std::to_string(getpid())), std::string::npos) << locked.err;
    EXPECT_NE(locked.err.find(set_dir), std::string::npos) << locked.err;
  }
  for (const char* shard : {"0/2", "3/2", "1", "a/b"}) {
    const auto bad = run(mine("--source " + quote(empty_frames()) + " --out " + quote(set_dir) + " --shard " + shard));
    EXPECT_EQ(bad.exit_code, 2) << shard;
    EXPECT_NE(bad.err.find("--shard"), std::string::npos) << bad.err;
  }
  EXPECT_TRUE(SampleSet::open_read(set_dir).records().empty());
}

TEST(Miner, ShardsPartitionTheStridedFrames) {
  rdsf::MineParams p;
  p.stride = 2;
  p.shard_count = 3;
  for (std::int64_t index = 0; index < 60; ++index) {
    int owners = 0;
    for (int shard = 1; shard <= 3; ++shard) {
      p.shard_index = shard;
      owners += rdsf::frame_selected(index, p) ? 1 : 0;
    }
    EXPECT_EQ(owners, index % 2 == 0 ? 1 : 0) << index;
  }
  p.shard_index = 2;
  EXPECT_TRUE(rdsf::frame_selected(2, p));  // k = 1 -> shard 2 of 3
  EXPECT_FALSE(rdsf::frame_selected(0, p));
  p.sources = {"x"};
  EXPECT_NO_THROW(rdsf::check_mine_params(p));
  p.shard_index = 4;
  EXPECT_THROW(rdsf::check_mine_params(p), rdsf::Error);
  p.shard_index = 1;
  p.stride = 0;
  EXPECT_THROW(rdsf::check_mine_params(p), rdsf::Error);
}

TEST(Miner, ResultDoesNotDependOnTheThreadCount) {
  RDSF_REQUIRE_REALDATA();
  rdsf::test::TempDir dir;
  for (int threads : {1, 2, 3}) {
    rdsf::MineParams p = params_for(empty_frames());
    p.threads = threads;
    rdsf::SampleSetWriter writer = new_set(dir / ("t" + std::to_string(threads)));
    const rdsf::MineStats stats = rdsf::mine_negatives(p, writer);
    EXPECT_EQ(stats.frames, 9);
    EXPECT_EQ(stats.kept, static_cast<std::int64_t>(writer.records().size()));
  }
  EXPECT_EQ(keys_of(dir / "t1"), keys_of(dir / "t2"));  // same order, not only the same samples
  EXPECT_EQ(keys_of(dir / "t1"), keys_of(dir / "t3"));
}

TEST(Miner, HardNegativeModeKeepsOnlyWhatTheModelScoresHigh) {
  RDSF_REQUIRE_REALDATA();
  rdsf::test::TempDir dir;
  // A stand-in model: the score is the first feature value (the similarity of the two top-left cells).
  rdsf::MineParams p = params_for(empty_frames());
  p.scorer = [](const cv::Mat1w& crop) { return static_cast<double>(rdsf::RdsfExtractor{}.compute(crop)[0]); };
  p.min_score = 0.5;
  p.model = "first-value/v1";
  rdsf::SampleSetWriter writer = new_set(dir / "hard");
  const rdsf::MineStats stats = rdsf::mine_negatives(p, writer);
  EXPECT_GT(stats.below_score, 0);
  EXPECT_GT(stats.kept, 0);
  EXPECT_EQ(stats.kept + stats.below_score, stats.candidates);
  writer.close();
  const SampleSet set = SampleSet::open_read(dir / "hard");
  const cv::Mat1f rows = set.features(rdsf::RdsfExtractor{});
  for (std::size_t i = 0; i < set.records().size(); ++i) {
    const rdsf::SampleRecord& r = set.records()[i];
    EXPECT_EQ(r.model, "first-value/v1");
    ASSERT_TRUE(r.score.has_value());
    EXPECT_GE(*r.score, 0.5);
    EXPECT_DOUBLE_EQ(*r.score, static_cast<double>(rows(static_cast<int>(i), 0)));
  }
}

TEST(Miner, MaxStopsAtTheNumberOfNegativesInTheSet) {
  RDSF_REQUIRE_REALDATA();
  rdsf::test::TempDir dir;
  rdsf::MineParams p = params_for(empty_frames());
  p.max_negatives = 7;
  {
    rdsf::SampleSetWriter writer = new_set(dir / "set");
    const rdsf::MineStats stats = rdsf::mine_negatives(p, writer);
    EXPECT_TRUE(stats.reached_max);
    EXPECT_EQ(writer.records().size(), 7u);
  }
  rdsf::SampleSetWriter writer = rdsf::SampleSetWriter::open_existing(dir / "set");
  const rdsf::MineStats stats = rdsf::mine_negatives(p, writer);  // resumed: already full
  EXPECT_EQ(stats.kept, 0);
  EXPECT_EQ(writer.records().size(), 7u);
}

TEST(Miner, ModelOptionKeepsTheModelsFalsePositivesWithTheirScores) {
  RDSF_REQUIRE_REALDATA();
  const std::string model_path = std::string(RDSF_SOURCE_DIR) + "/tests/reference_models/rdsf-model-v1-native.yml";
  if (!fs::exists(model_path)) GTEST_SKIP() << model_path << " is absent";
  const rdsf::BoostedModel model = rdsf::BoostedModel::load(model_path);
  rdsf::test::TempDir dir;
  const std::string all = dir / "all", hard = dir / "hard";
  ASSERT_EQ(run(mine("--source " + quote(empty_frames()) + " --out " + quote(all))).exit_code, 0);
  const auto result = run(mine("--source " + quote(empty_frames()) + " --out " + quote(hard) + " --model " +
                               quote(model_path) + " --min-score 0"));
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("acceptance ratio"), std::string::npos) << result.err;

  // Exactly the candidates of the plain run that the model scores at or above 0.
  const SampleSet every = SampleSet::open_read(all);
  const std::vector<double> scores = model.score(every.features(rdsf::RdsfExtractor{}));
  std::vector<Key> expected;
  const std::vector<Key> every_key = keys_of(all);
  for (std::size_t i = 0; i < scores.size(); ++i) {
    if (scores[i] >= 0) expected.push_back(every_key[i]);
  }
  EXPECT_GT(expected.size(), 0u);
  EXPECT_LT(expected.size(), every_key.size());  // the threshold did select
  EXPECT_EQ(keys_of(hard), expected);
  const SampleSet set = SampleSet::open_read(hard);
  const std::vector<double> again = model.score(set.features(rdsf::RdsfExtractor{}));
  for (std::size_t i = 0; i < set.records().size(); ++i) {
    const rdsf::SampleRecord& r = set.records()[i];
    EXPECT_EQ(r.model, model.name() + "/v" + std::to_string(model.version()));
    ASSERT_TRUE(r.score.has_value());
    EXPECT_NEAR(*r.score, again[i], 1e-9);
    EXPECT_GE(*r.score, 0.0);
  }
  // --min-score alone is a usage error.
  EXPECT_EQ(run(mine("--source " + quote(empty_frames()) + " --out " + quote(dir / "x") + " --min-score 1")).exit_code,
            2);
}

TEST(Miner, DepthOnlyGivesTheSameSamplesWithoutColour) {
  RDSF_REQUIRE_REALDATA();
  rdsf::test::TempDir dir;
  for (bool depth_only : {false, true}) {
    rdsf::MineParams p = params_for(empty_frames());
    p.depth_only = depth_only;
    rdsf::SampleSetWriter writer = new_set(dir / (depth_only ? "depth" : "colour"));
    rdsf::mine_negatives(p, writer);
  }
  EXPECT_EQ(keys_of(dir / "depth"), keys_of(dir / "colour"));
  const SampleSet colour = SampleSet::open_read(dir / "colour"), depth = SampleSet::open_read(dir / "depth");
  EXPECT_TRUE(colour.records().front().has_colour);  // the real frames have colour
  for (const rdsf::SampleRecord& r : depth.records()) EXPECT_FALSE(r.has_colour);
  EXPECT_FALSE(fs::exists(depth.colour_crop_path(0)));
}

TEST(Miner, BadSourceFailsBeforeTheSetIsCreated) {
  rdsf::test::TempDir dir;
  const auto result = run(mine("--source " + quote(dir / "no-such-folder") + " --out " + quote(dir / "set")));
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find(dir / "no-such-folder" + ": no such file or folder"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(dir / "set"));
}

// Mining at scale (issue 37): scripts/shard-mine.sh mines a list of recordings in 3 shards over GNU parallel
// and merges them; scripts/slurm/mine-array.sbatch does each shard as an array task (run here with the
// variables Slurm sets, no Slurm daemons) and the merge. Both merged sets hold exactly the samples of one
// rdsf-mine over the list: the same (label, source, frame, boxes, crop hash) rows, compared sorted (ids and
// order differ by design).
TEST(Miner, ShardMineScriptAndSlurmArrayEqualOneRun) {
  if (run("command -v parallel").exit_code != 0) GTEST_SKIP() << "GNU parallel is absent (Debian: parallel): skipped";
  rdsf::test::TempDir dir;
  std::string list_text, sources;
  for (int k = 1; k <= 3; ++k) {  // three short people-free recordings of other lengths
    const std::string recording = dir / ("recording" + std::to_string(k));
    ASSERT_EQ(run(quote(rdsf::test::program("rdsf-synth")) + " --out " + quote(recording) + " --frames " +
                  std::to_string(4 + k) + " --seed " + std::to_string(k) + " --empty --clip-frames 4")
                  .exit_code,
              0);
    list_text += recording + "\n";
    sources += " " + quote(recording);
  }
  std::ofstream(dir / "list.txt") << "# people-free rooms\n" << list_text;
  const std::string whole = dir / "whole";
  ASSERT_EQ(run(mine("--source" + sources + " --out " + quote(whole))).exit_code, 0);
  const std::vector<Key> expected = sorted(keys_of(whole));
  ASSERT_GT(expected.size(), 10u);

  const std::string env = "RDSF_BUILD_DIR=" + quote(RDSF_BINARY_DIR) + " ";
  const std::string script = quote(std::string(RDSF_SOURCE_DIR) + "/scripts/shard-mine.sh");
  const auto sharded = run(env + script + " --list " + quote(dir / "list.txt") + " --out " + quote(dir / "merged") +
                           " --shards 3 -- --threads 1");
  ASSERT_EQ(sharded.exit_code, 0) << sharded.err << sharded.out;
  EXPECT_NE(sharded.out.find("shard 3/3"), std::string::npos) << sharded.out;
  EXPECT_EQ(sorted(keys_of(dir / "merged")), expected);

  // Array indices 0-2 (Slurm's --array=0-2), then the merge job.
  const std::string sbatch = "SLURM_SUBMIT_DIR=" + quote(RDSF_SOURCE_DIR) + " " + env + "bash " +
                             quote(std::string(RDSF_SOURCE_DIR) + "/scripts/slurm/mine-array.sbatch");
  const std::string sets = " " + quote(dir / "list.txt") + " " + quote(dir / "slurm");
  for (int task = 0; task <= 2; ++task) {
    const auto result = run("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_MAX=2 " +
                            sbatch + sets + " -- --threads 1");
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_NE(result.err.find("shard " + std::to_string(task + 1) + "/3"), std::string::npos) << result.err;
  }
  const auto merged = run(sbatch + " --merge" + sets);
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_EQ(sorted(keys_of(dir / "slurm")), expected);
  // Outside an array task the per-shard step refuses to run.
  EXPECT_NE(run(sbatch + sets).exit_code, 0);
}
