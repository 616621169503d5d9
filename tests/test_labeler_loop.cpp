// rdsf-label --loop with the truth as the person (--truth-oracle): batches, a model trained and saved after
// each, the model version recorded with the answers given under it, and the last model answering what it is
// sure about at the end; plus the ordering pieces (most uncertain first, suspicion).
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "rdsf/dataset/sample_set.hpp"
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
