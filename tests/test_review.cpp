// rdsf-review headless (--keys): flip and retract are on disk at once and journalled, the most suspicious
// sample comes first under a model, a half-done flip of a killed review is finished, and a set another
// program writes or a model of another feature spec is refused with one line, nothing changed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_lock.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/pipeline/model_scorer.hpp"
#include "support/depth_scenes.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

std::string models() { return test::quote(std::string(RDSF_SOURCE_DIR) + "/models"); }

// Six samples from two frames: a#0 person, the other five not people (stored: --keep-rejected).
void make_set(const test::TempDir& dir, const std::string& extra = "") {
  test::write_two_person_frames(dir / "frames");
  std::ofstream(dir / "answers") << "y n n n n n";
  const test::RunResult r = test::run(test::quote(test::program("rdsf-label")) + " --source " + test::quote(dir / "frames") +
                                      " --out " + test::quote(dir / "set") + " --answers " + test::quote(dir / "answers") +
                                      " --keep-rejected " + extra);
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

test::RunResult review(const test::TempDir& dir, const std::string& keys, const std::string& extra = "") {
  std::ofstream(dir / "keys") << keys;
  return test::run(test::quote(test::program("rdsf-review")) + " --set " + test::quote(dir / "set") + " --keys " +
                   test::quote(dir / "keys") + " --models-dir " + models() + " " + extra);
}

std::size_t lines(const std::string& path) {
  std::ifstream in(path);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

}  // namespace

TEST(Review, FlipAndRetractAreSavedAndJournalled) {
  test::TempDir dir;
  make_set(dir);
  // By origin (all "labeler"), then id: 1 (the person) is selected first: flip it, move right, retract 2.
  const test::RunResult r = review(dir, "f right x q", "--sort origin");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("flipped 1, retracted 1"), std::string::npos) << r.err;
  const SampleSet set = SampleSet::open_read(dir / "set");
  ASSERT_EQ(set.records().size(), 5u);  // 6 - 2 retracted + 1 corrected
  const SampleRecord& corrected = set.records().back();
  EXPECT_EQ(corrected.id, 7);
  EXPECT_EQ(corrected.label, 0);
  EXPECT_EQ(corrected.origin, "review");
  EXPECT_EQ(corrected.frame, "a");
  EXPECT_EQ(corrected.strict_box, cv::Rect(230, 100, 180, 360));  // the place of sample 1
  EXPECT_EQ(set.depth_crop(set.records().size() - 1).size(), cv::Size(64, 128));
  for (const SampleRecord& s : set.records()) EXPECT_TRUE(s.id != 1 && s.id != 2) << s.id;
  EXPECT_EQ(lines(dir / "set/review-changes.tsv"), 3u);  // header, flip, retract
  EXPECT_EQ(set.count(1), 0u);
}

TEST(Review, OpenFramePrintsWhereTheSampleCameFrom) {
  test::TempDir dir;
  make_set(dir);
  const test::RunResult r = review(dir, "right right right o q", "--sort source");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("sample 4: frame b of"), std::string::npos) << r.out;  // ids 1-3 are frame a
}

TEST(Review, MostSuspiciousFirstUnderAModel) {
  test::TempDir dir;
  const test::RunResult synth = test::run(test::quote(test::program("rdsf-synth")) + " --out " + test::quote(dir / "synth") +
                                          " --frames 8 --people 1..2 --seed 3");
  ASSERT_EQ(synth.exit_code, 0) << synth.err;
  // Every candidate labelled a person: the one the model finds least like a person is the most suspicious.
  std::ofstream(dir / "answers") << std::string(300, 'y');
  ASSERT_EQ(test::run(test::quote(test::program("rdsf-label")) + " --source " + test::quote(dir / "synth") + " --out " +
                      test::quote(dir / "set") + " --answers " + test::quote(dir / "answers"))
                .exit_code,
            0);
  const BoostedModel model = BoostedModel::load(std::string(RDSF_SOURCE_DIR) + "/models/people/v4.yml");
  const SampleSet before = SampleSet::open_read(dir / "set");
  ASSERT_GT(before.records().size(), 3u);
  ModelScorer scorer(model);
  std::int64_t least = -1;
  double lowest = 2;
  for (std::size_t i = 0; i < before.records().size(); ++i) {
    const double p = model.probability(scorer.score(before.depth_crop(i)));
    if (p < lowest) lowest = p, least = before.records()[i].id;
  }
  const test::RunResult r = review(dir, "f q", "--model people");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("most suspicious first"), std::string::npos) << r.err;
  const SampleSet after = SampleSet::open_read(dir / "set");
  EXPECT_EQ(after.count(0), 1u);
  for (const SampleRecord& s : after.records()) EXPECT_NE(s.id, least);  // the flipped one is gone
  EXPECT_EQ(after.records().back().model, "people/v4");  // --model people: the newest shipped
}

TEST(Review, HalfDoneFlipOfAKilledReviewIsFinished) {
  test::TempDir dir;
  make_set(dir);
  {  // A review killed after appending the corrected sample, before retracting the original.
    SampleSetWriter writer = SampleSetWriter::open_existing(dir / "set");
    const SampleSet set = SampleSet::open_read(dir / "set");
    SampleRecord corrected = set.records()[0];
    corrected.label = 0;
    corrected.origin = "review";
    corrected.time.clear();
    writer.append(corrected, set.depth_crop(0));
  }
  const test::RunResult r = review(dir, "q", "--sort origin");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("finished 1 flip"), std::string::npos) << r.err;
  const SampleSet set = SampleSet::open_read(dir / "set");
  EXPECT_EQ(set.records().size(), 6u);
  EXPECT_EQ(set.count(1), 0u);  // sample 1 (the person) retracted: its correction is in force
  // Finished once: a second review finds nothing to finish.
  const test::RunResult again = review(dir, "q", "--sort origin");
  EXPECT_EQ(again.err.find("finished"), std::string::npos) << again.err;
}

TEST(Review, ASetAnotherProgramWritesIsRefused) {
  test::TempDir dir;
  make_set(dir);
  const SampleSetLock held(dir / "set");
  const auto before = std::filesystem::file_size(dir / "set/samples.tsv");
  const test::RunResult r = review(dir, "f q", "--sort origin");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("being written by another program"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(std::filesystem::file_size(dir / "set/samples.tsv"), before);
  EXPECT_FALSE(std::filesystem::exists(dir / "set/review-changes.tsv"));
}

TEST(Review, ModelOfAnotherFeatureSpecIsRefused) {
  test::TempDir dir;
  make_set(dir, "--feature-spec rdsf:cell=16");
  const test::RunResult r = review(dir, "f q", "--model people");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("the model reads feature spec"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "set/review-changes.tsv"));
}

TEST(Review, SuspicionWithoutAModelIsAUsageError) {
  test::TempDir dir;
  make_set(dir);
  const test::RunResult r = review(dir, "q", "--sort suspicion");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--sort suspicion needs --model or --folds"), std::string::npos) << r.err;
}

TEST(Review, OutOfFoldScoresPutAPlantedLabelErrorAmongTheFirst) {
  test::TempDir dir;
  ASSERT_EQ(test::run(test::quote(test::program("rdsf-synth")) + " --out " + test::quote(dir / "synth") +
                      " --frames 60 --people 1..3 --seed 5 --clip-frames 10")
                .exit_code,
            0);
  // Labelled from the truth (assisted mode, rejections kept), then one not-person planted as a person.
  std::ofstream(dir / "answers") << "";
  ASSERT_EQ(test::run(test::quote(test::program("rdsf-label")) + " --source " + test::quote(dir / "synth") + " --out " +
                      test::quote(dir / "set") + " --truth " + test::quote(dir / "synth/boxes.csv") +
                      " --answers /dev/null --keep-rejected")
                .exit_code,
            0);
  const SampleSet labelled = SampleSet::open_read(dir / "set");
  ASSERT_GT(labelled.count(1), 10u);
  std::size_t other = 0;
  while (labelled.records()[other].label != 0) ++other;
  const test::RunResult plant = review(dir, std::string(other, 'l') + " f q", "--sort origin");
  ASSERT_EQ(plant.exit_code, 0) << plant.err;
  const std::int64_t planted = SampleSet::open_read(dir / "set").records().back().id;
  const test::RunResult r = review(dir, "q", "--folds 5 --list 100000");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // A wall labelled a person is among the most suspicious (with this few frames, persons the other folds
  // never saw come first; the benchmark on 600 frames finds 86% of planted flips in the first 5%).
  const auto at = r.out.find("\tsample " + std::to_string(planted) + "\tlabel 1\t");
  ASSERT_NE(at, std::string::npos) << r.out;
  const long position = std::stol(r.out.substr(r.out.rfind('\n', at) + 1));
  const long shown = static_cast<long>(std::count(r.out.begin(), r.out.end(), '\n'));
  std::cout << "planted error at " << position << " of " << shown << "\n";
  EXPECT_LE(position, shown / 10) << r.out.substr(0, 2000);
}
