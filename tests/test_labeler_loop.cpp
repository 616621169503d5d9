// rdsf-label --loop with the truth as the person (--truth-oracle): batches, a model trained and saved after
// each, the model version recorded with the answers given under it, and the last model answering what it is
// sure about at the end; the same loop with one answer per track (--per-track), and with keys that undo a
// track's answer after a model was trained on it; plus the ordering pieces (most uncertain first, suspicion).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <set>

#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/labeling/answer_journal.hpp"
#include "rdsf/labeling/track_propagation.hpp"
#include "rdsf/labeling/active_learning.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

TEST(ActiveLearning, MostUncertainFirstAndSuspicion) {
  const std::vector<std::size_t> order = most_uncertain_first({0.9, 0.45, 0.02, 0.55, 0.7});
  EXPECT_EQ(order, (std::vector<std::size_t>{1, 3, 4, 0, 2}));  // 0.45 and 0.55 tie: index order
  EXPECT_DOUBLE_EQ(suspicion(1, 0.2), 0.8);
  EXPECT_DOUBLE_EQ(suspicion(0, 0.2), 0.2);
}

TEST(ActiveLearning, NoModelWithTooFewOfAClass) {
  cv::Mat1f rows(8, FeatureSpec{}.dimension(), 0.5f);
  const std::vector<int> labels{1, 1, 0, 0, 0, 0, 0, 0};
  EXPECT_FALSE(train_loop_model(rows, labels, {}, FeatureSpec{}, LoopTrainingParams{}).has_value());
}

TEST(LabelerLoop, BatchesRetrainRecordTheModelVersionAndTheLastModelAnswers) {
  test::TempDir dir;
  const test::RunResult synth = test::run(test::quote(test::program("rdsf-synth")) + " --out " +
                                          test::quote(dir / "synth") + " --frames 30 --people 1..3 --seed 4 --clip-frames 10");
  ASSERT_EQ(synth.exit_code, 0) << synth.err;
  const test::RunResult r = test::run(
      test::quote(test::program("rdsf-label")) + " --source " + test::quote(dir / "synth") + " --out " +
      test::quote(dir / "set") + " --truth " + test::quote(dir / "synth/boxes.csv") +
      " --truth-oracle --loop --batch 15 --budget 60 --loop-answer-after 3 --accept 0.9 --reject 0.1 --models-dir " + test::quote(dir / "models") +
      // the candidates this scene was written for (head splitting changes their order: the first batch
      // would hold enough people to train on)
      " --split-head-drop 0");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The first batch has too few people to train on; then a model after every batch of 15.
  EXPECT_NE(r.err.find("loop: 15 answers; too few of a class"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("loop: 30 answers"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("loop: 60 answers"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("answered 60 "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("candidates it is sure about"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("truth oracle: "), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "models/loop/v1.yml"));
  EXPECT_TRUE(std::filesystem::exists(dir / "models/loop/v2.yml"));
  EXPECT_TRUE(std::filesystem::exists(dir / "models/loop/v3.yml"));  // after the last batch, for the end
  EXPECT_FALSE(std::filesystem::exists(dir / "models/loop/v4.yml"));
  const SampleSet set = SampleSet::open_read(dir / "set");
  std::set<std::string> versions;
  std::size_t human = 0, by_model = 0;
  for (const SampleRecord& s : set.records()) {
    if (s.origin == "labeler") {
      ++human;
      versions.insert(s.model);  // "" for the first two batches (no model yet), then loop/v1, loop/v2
    } else {
      EXPECT_EQ(s.origin, "labeler-model");
      EXPECT_EQ(s.model, "loop/v3");
      ++by_model;
    }
  }
  EXPECT_GT(human, 20u);  // y and n stored (--loop keeps rejections); skips are not
  EXPECT_TRUE(versions.count("") && versions.count("loop/v1") && versions.count("loop/v2")) << versions.size();
  EXPECT_GT(by_model, 0u);
}

namespace {

test::RunResult render_room(const std::filesystem::path& out) {
  return test::run(test::quote(test::program("rdsf-synth")) + " --out " + test::quote(out) +
                   " --frames 40 --people 1..2 --seed 5 --clip-frames 40");
}

}  // namespace

// --loop with --per-track, the truth as the person: each human answer labels its track, the loop's models are
// trained on the propagated samples too, and the budget counts human answers only.
TEST(LabelerLoop, PerTrackAnswersLabelTheirTracksAndTheLoopTrainsOnThem) {
  test::TempDir dir;
  ASSERT_EQ(render_room(dir / "room").exit_code, 0);
  const test::RunResult r = test::run(
      test::quote(test::program("rdsf-label")) + " --source " + test::quote(dir / "room") + " --out " +
      test::quote(dir / "set") + " --truth " + test::quote(dir / "room/boxes.csv") +
      " --truth-oracle --loop --per-track --batch 10 --budget 30 --loop-answer-after 3 --threads 2 --models-dir " +
      test::quote(dir / "models"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m, std::regex("per track: ([0-9]+) labels propagated"))) << r.err;
  const long propagated = std::stol(m[1]);
  EXPECT_GT(propagated, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "models/loop/v1.yml")) << r.err;
  // The first model trained after 10 human answers saw more than 10 samples: the tracks' labels.
  ASSERT_TRUE(std::regex_search(r.err, m, std::regex("loop/v1 trained on ([0-9]+) samples"))) << r.err;
  std::size_t human = 0, by_track = 0;
  const SampleSet set = SampleSet::open_read(dir / "set");
  for (const SampleRecord& s : set.records()) {
    human += s.origin == "labeler" ? 1 : 0;
    by_track += s.origin == "labeler-track" || s.origin == "labeler-place" ? 1 : 0;
  }
  EXPECT_GT(std::stoul(m[1]), 10u) << r.err;
  EXPECT_GT(by_track, 0u);
  EXPECT_LE(human, 30u);  // the budget counts the person's answers, not the propagated labels
  // Every propagated label names an answer in force as its seed (what undo takes back with it).
  const AnswerJournal journal(dir / "set/labeler-answers.tsv");
  std::set<std::string> seeds;
  long journalled = 0;
  for (const JournalEntry& e : journal.in_force()) {
    if (e.by == "human") seeds.insert({track_answerer(e.key), place_answerer(e.key)});
  }
  for (const JournalEntry& e : journal.in_force()) {  // along a track, or to the answer's place (per place)
    if (e.by.rfind("track ", 0) != 0 && e.by.rfind("place ", 0) != 0) continue;
    ++journalled;
    EXPECT_TRUE(seeds.count(e.by)) << e.by;
  }
  EXPECT_EQ(journalled, propagated);
}

// Scripted keys: the tenth answer, given before the loop's first retrain, is undone after it (the frames
// were scored again by the new model in between); its whole track goes with it, and the set keeps no sample
// of it.
TEST(LabelerLoop, PerTrackUndoAfterARetrainTakesTheWholeTrackBack) {
  test::TempDir dir;
  ASSERT_EQ(render_room(dir / "room").exit_code, 0);
  std::ofstream(dir / "keys.txt") << "y n y n y n y n y n u q\n";
  const test::RunResult r = test::run(
      test::quote(test::program("rdsf-label")) + " --source " + test::quote(dir / "room") + " --out " +
      test::quote(dir / "set") + " --answers " + test::quote(dir / "keys.txt") +
      " --loop --per-track --batch 10 --loop-answer-after 1000 --threads 2 --models-dir " + test::quote(dir / "models"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(std::filesystem::exists(dir / "models/loop/v1.yml")) << r.err;  // trained before the undo
  EXPECT_FALSE(std::filesystem::exists(dir / "models/loop/v2.yml")) << r.err;
  EXPECT_NE(r.err.find("undone 1)"), std::string::npos) << r.err;
  // The journal's lines: the human answers in file order, and the undo lines.
  std::vector<JournalEntry> human;
  long undo_lines = 0;
  std::ifstream in(dir / "set/labeler-answers.tsv");
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string x; std::getline(fields, x, '\t');) f.push_back(x);
    if (f.size() < 10 || f[0] == "time") continue;
    if (f[7] == "u") ++undo_lines;
    if (f[7] != "u" && f[9] == "human") {
      human.push_back({{f[1], f[2], {std::stoi(f[3]), std::stoi(f[4]), std::stoi(f[5]), std::stoi(f[6])}}, f[7][0]});
    }
  }
  ASSERT_EQ(human.size(), 10u) << r.err;
  const AnswerJournal journal(dir / "set/labeler-answers.tsv");
  // Its labels: along its track, and (an n, per place) at its place.
  const std::string undone_by[] = {track_answerer(human.back().key), place_answerer(human.back().key)};
  const auto by_undone = [&](const std::string& by) { return by == undone_by[0] || by == undone_by[1]; };
  EXPECT_EQ(journal.answer_of(human.back().key), '\0');  // the tenth answer is no longer in force
  long track_in_force = 0, propagated_in_force = 0;
  for (const JournalEntry& e : journal.in_force()) {
    track_in_force += by_undone(e.by) ? 1 : 0;
    propagated_in_force += e.by.rfind("track ", 0) == 0 || e.by.rfind("place ", 0) == 0 ? 1 : 0;
  }
  EXPECT_EQ(track_in_force, 0);
  // Undo lines: the answer and each label of its track and place.
  std::ifstream again(dir / "set/labeler-answers.tsv");
  long track_lines = 0;
  for (std::string line; std::getline(again, line);) {
    const std::string by = line.substr(line.rfind('\t') + 1);
    track_lines += by_undone(by) && line.find("\tu\t") == std::string::npos ? 1 : 0;
  }
  EXPECT_GT(track_lines, 0) << r.err;
  EXPECT_EQ(undo_lines, 1 + track_lines) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.err, m, std::regex("per track: ([0-9]+) labels propagated"))) << r.err;
  EXPECT_EQ(std::stol(m[1]), propagated_in_force);
  std::size_t by_track = 0;
  const SampleSet set = SampleSet::open_read(dir / "set");
  for (const SampleRecord& s : set.records()) by_track += s.origin == "labeler-track" || s.origin == "labeler-place" ? 1 : 0;
  EXPECT_EQ(by_track, static_cast<std::size_t>(propagated_in_force));  // --loop keeps y and n: every label stored
}
