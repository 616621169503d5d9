// The classifier library: metrics, sampling, binning, the native Real AdaBoost trainer and the OpenCV
// backend, on feature matrices made here (no sample sets needed).
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "rdsf/classifier/binned_matrix.hpp"
#include "rdsf/classifier/boost_training.hpp"
#include "rdsf/classifier/model_file.hpp"
#include "rdsf/classifier/opencv_boost.hpp"
#include "rdsf/classifier/real_adaboost.hpp"
#include "rdsf/classifier/roc_metrics.hpp"
#include "rdsf/classifier/seeded_sampling.hpp"
#include "classifier_support/toy_data.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {
namespace {

TEST(RocMetrics, PerfectReversedAndTiedScores) {
  const std::vector<int> labels = {1, 1, 0, 0};
  EXPECT_DOUBLE_EQ(roc_auc({0.9, 0.8, 0.1, 0.2}, labels), 1.0);
  EXPECT_DOUBLE_EQ(roc_auc({0.1, 0.2, 0.9, 0.8}, labels), 0.0);
  EXPECT_DOUBLE_EQ(roc_auc({0.5, 0.5, 0.5, 0.5}, labels), 0.5);
  EXPECT_THROW(roc_auc({0.1, 0.2}, {1, 1}), Error);
  EXPECT_THROW(roc_auc({0.1}, {1, 0}), Error);
}

TEST(RocMetrics, TarAtFarAndErrorRate) {
  // 100 negatives scoring -1 .. -0.01 except two high ones; 10 positives.
  std::vector<double> scores;
  std::vector<int> labels;
  for (int i = 0; i < 98; ++i) {
    scores.push_back(-1.0 + i * 0.01);
    labels.push_back(0);
  }
  scores.push_back(5.0);  // a negative above every positive
  labels.push_back(0);
  scores.push_back(0.5);  // a negative between positives
  labels.push_back(0);
  for (int i = 0; i < 10; ++i) {
    scores.push_back(i < 5 ? 1.0 + i : 0.1 + i * 0.01);
    labels.push_back(1);
  }
  const RocSummary s = summarise_roc(scores, labels);
  EXPECT_DOUBLE_EQ(s.tar_at_far_1, 0.5);   // FAR 1 %: only the 5.0 negative passes: positives above 0.5
  EXPECT_DOUBLE_EQ(s.tar_at_far_5, 1.0);   // FAR 2 % admits all positives
  EXPECT_NEAR(s.error_rate, 2.0 / 110.0, 1e-12);
  const std::vector<RocPoint> levels = roc_at_far_levels(roc_curve(scores, labels));
  ASSERT_FALSE(levels.empty());
  EXPECT_DOUBLE_EQ(levels.back().far, 0.02);  // the first point reaching TAR 1 serves every higher level
  EXPECT_DOUBLE_EQ(levels.back().tar, 1.0);
  EXPECT_DOUBLE_EQ(levels.front().tar, 0.0);  // FAR 0.1 %: nothing passes above the 5.0 negative
}

TEST(SeededSampling, SubsetIsSeededDistinctAndSorted) {
  const auto a = seeded_subset(1000, 100, 7), b = seeded_subset(1000, 100, 7), c = seeded_subset(1000, 100, 8);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  EXPECT_EQ(std::set<std::size_t>(a.begin(), a.end()).size(), 100u);
  EXPECT_TRUE(std::is_sorted(a.begin(), a.end()));
  EXPECT_EQ(seeded_subset(10, 50, 1).size(), 10u);
}

TEST(SeededSampling, StratifiedSplitKeepsClassProportions) {
  std::vector<int> labels(1000, 0);
  for (int i = 0; i < 200; ++i) labels[static_cast<std::size_t>(i * 5)] = 1;
  const HoldOutSplit s = stratified_split(labels, 0.25, 3);
  EXPECT_EQ(s.train.size() + s.validation.size(), 1000u);
  std::size_t val_pos = 0;
  for (std::size_t i : s.validation) val_pos += static_cast<std::size_t>(labels[i]);
  EXPECT_EQ(val_pos, 50u);
  EXPECT_EQ(s.validation.size(), 250u);
  std::vector<std::size_t> both = s.train;
  both.insert(both.end(), s.validation.begin(), s.validation.end());
  EXPECT_EQ(std::set<std::size_t>(both.begin(), both.end()).size(), 1000u);
  EXPECT_EQ(stratified_split(labels, 0.25, 3).validation, s.validation);
  EXPECT_NE(stratified_split(labels, 0.25, 4).validation, s.validation);
  EXPECT_THROW(stratified_split(labels, 1.0, 3), Error);
}

TEST(BinnedMatrix, FeatureMajorBinsWithRowOrder) {
  cv::Mat1f rows(3, 4);
  rows << 0.0f, 0.5f, 1.0f, -0.2f,  //
      0.999f, 0.25f, 0.015625f, 2.0f,  //
      0.49f, 0.51f, 0.75f, 0.1f;
  const BinScheme scheme;  // 64 bins over [0, 1]
  const BinnedMatrix m(rows, scheme, {2, 0}, 2);
  ASSERT_EQ(m.samples(), 2u);
  ASSERT_EQ(m.features(), 4u);
  EXPECT_EQ(m.at(0, 0), 31);  // 0.49 * 64 = 31.36
  EXPECT_EQ(m.at(0, 1), 0);
  EXPECT_EQ(m.at(1, 1), 32);  // 0.5 -> bin 32
  EXPECT_EQ(m.at(2, 1), 63);  // 1.0 -> last bin
  EXPECT_EQ(m.at(3, 1), 0);   // below range
  EXPECT_EQ(scheme.bin_of(0.015625f), 1);
  EXPECT_EQ(scheme.bin_of(2.0f), 63);
  EXPECT_THROW(BinnedMatrix(rows, BinScheme{1, 0.0f, 1.0f}), Error);
  EXPECT_THROW(BinnedMatrix(rows, scheme, {3}), Error);
}

TEST(RealAdaBoost, LearnsASeparableToyProblemExactly) {
  const test::ToyData toy = test::separable_toy(300, 1234, 11);
  const BinnedMatrix binned(toy.rows, BinScheme{});
  RealAdaBoost booster(binned, toy.labels);
  const RealAdaBoostRound r = booster.next_round();
  EXPECT_EQ(r.feature, 1234);
  EXPECT_EQ(r.round, 1);
  EXPECT_DOUBLE_EQ(r.train_error, 0.0);
  EXPECT_LT(r.z, 1e-9);
  const WeakClassifier& w = booster.weak_classifiers().front();
  for (int bin = 0; bin < 32; ++bin) EXPECT_LE(w.responses[static_cast<std::size_t>(bin)], 0.0) << bin;
  for (int bin = 32; bin < 64; ++bin) EXPECT_GE(w.responses[static_cast<std::size_t>(bin)], 0.0) << bin;
  for (std::size_t i = 0; i < toy.labels.size(); ++i) {
    EXPECT_EQ(booster.train_scores()[i] > 0.0, toy.labels[i] == 1);
  }
}

TEST(RealAdaBoost, ResultDoesNotDependOnThreadCount) {
  const test::ToyData toy = test::noisy_toy(400, 5);
  const BinnedMatrix binned(toy.rows, BinScheme{});
  RealAdaBoostParams one;
  one.threads = 1;
  RealAdaBoostParams three = one;
  three.threads = 3;
  RealAdaBoost a(binned, toy.labels, one), b(binned, toy.labels, three);
  for (int round = 0; round < 5; ++round) {
    const RealAdaBoostRound ra = a.next_round(), rb = b.next_round();
    EXPECT_EQ(ra.feature, rb.feature);
    EXPECT_EQ(ra.z, rb.z);
  }
  EXPECT_EQ(a.weak_classifiers(), b.weak_classifiers());
}

TEST(RealAdaBoost, PositivesFirstLayoutChoosesTheSameFeatures) {
  // The four-feature path (samples ordered positives first) and the general path agree.
  const test::ToyData toy = test::noisy_toy(400, 8);
  const std::vector<std::size_t> order = positives_first_order(toy.labels);
  ASSERT_EQ(order.size(), toy.labels.size());
  std::vector<int> ordered_labels;
  for (std::size_t i : order) ordered_labels.push_back(toy.labels[i]);
  EXPECT_TRUE(std::is_sorted(ordered_labels.begin(), ordered_labels.end(), [](int a, int b) { return a > b; }));
  const BinnedMatrix shuffled(toy.rows, BinScheme{}), sorted(toy.rows, BinScheme{}, order);
  RealAdaBoost general(shuffled, toy.labels), fast(sorted, ordered_labels);
  for (int round = 0; round < 6; ++round) {
    const RealAdaBoostRound a = general.next_round(), b = fast.next_round();
    EXPECT_EQ(a.feature, b.feature);
    EXPECT_NEAR(a.z, b.z, 1e-12);
    EXPECT_DOUBLE_EQ(a.train_error, b.train_error);
  }
  for (std::size_t k = 0; k < general.weak_classifiers().size(); ++k) {
    for (std::size_t j = 0; j < 64; ++j) {
      EXPECT_NEAR(general.weak_classifiers()[k].responses[j], fast.weak_classifiers()[k].responses[j], 1e-9);
    }
  }
}

TEST(RealAdaBoost, WeightTrimmingStillLearns) {
  const test::ToyData toy = test::separable_toy(300, 77, 12);
  const BinnedMatrix binned(toy.rows, BinScheme{});
  RealAdaBoostParams params;
  params.weight_trim = 0.1;
  RealAdaBoost booster(binned, toy.labels, params);
  const RealAdaBoostRound r1 = booster.next_round();
  EXPECT_EQ(r1.feature, 77);
  EXPECT_EQ(r1.samples_used, 271u);  // 90 % of the (uniform) weight
  EXPECT_DOUBLE_EQ(r1.train_error, 0.0);
  const RealAdaBoostRound r2 = booster.next_round();
  EXPECT_LT(r2.samples_used, 300u);
  EXPECT_DOUBLE_EQ(r2.train_error, 0.0);
}

TEST(RealAdaBoost, RefusesBadInput) {
  const test::ToyData toy = test::separable_toy(20, 3, 1);
  const BinnedMatrix binned(toy.rows, BinScheme{});
  EXPECT_THROW(RealAdaBoost(binned, std::vector<int>(19, 0)), Error);
  EXPECT_THROW(RealAdaBoost(binned, std::vector<int>(20, 1)), Error);
  std::vector<int> labels = toy.labels;
  labels[0] = 2;
  EXPECT_THROW(RealAdaBoost(binned, labels), Error);
}

TEST(BoostTraining, SameSeedSameModelFile) {
  const test::ToyData toy = test::noisy_toy(500, 21);
  BoostTrainingParams params;
  params.rounds = 8;
  params.seed = 5;
  const std::string a = model_file_text(train_boosted_model(toy.rows, toy.labels, params));
  params.threads = 1;
  const std::string b = model_file_text(train_boosted_model(toy.rows, toy.labels, params));
  EXPECT_EQ(a, b);
  params.seed = 6;  // another validation split: another model
  const std::string c = model_file_text(train_boosted_model(toy.rows, toy.labels, params));
  EXPECT_NE(a, c);
}

TEST(BoostTraining, ValidationFiguresProgressAndEarlyStopping) {
  const test::ToyData toy = test::separable_toy(400, 600, 31);
  BoostTrainingParams params;
  params.depth = 1;  // the thesis's weak learner: one round separates the toy exactly
  params.learning_rate = 1.0;
  params.rounds = 12;
  params.report_every = 5;
  params.early_stopping = 3;
  std::vector<TrainingProgress> reports;
  const BoostedModel model =
      train_boosted_model(toy.rows, toy.labels, params, [&](const TrainingProgress& p) { reports.push_back(p); });
  // AUC 1 after round 1, no better afterwards: stops at round 4, keeps round 1.
  ASSERT_EQ(reports.size(), 4u);
  EXPECT_EQ(reports.front().feature, 600);
  ASSERT_TRUE(reports.front().validation_auc.has_value());
  EXPECT_DOUBLE_EQ(*reports.front().validation_auc, 1.0);
  EXPECT_EQ(reports.back().round, 4);
  EXPECT_EQ(model.weak_classifiers().size(), 1u);
  const TrainingRecord& t = model.training();
  EXPECT_EQ(t.stopped.rfind("early stopping at round 4", 0), 0u) << t.stopped;
  EXPECT_EQ(t.validation.positives + t.validation.negatives, 80u);
  EXPECT_EQ(t.train_positives + t.train_negatives, 320u);
  EXPECT_DOUBLE_EQ(t.validation.summary.auc, 1.0);
  EXPECT_DOUBLE_EQ(t.validation.summary.tar_at_far_1, 1.0);
  ASSERT_EQ(t.validation.rounds.size(), 1u);  // round 1 is the last kept
  EXPECT_EQ(t.validation.rounds.front().round, 1);
}

TEST(BoostTraining, SeparateValidationSetAndBadParameters) {
  const test::ToyData train = test::noisy_toy(400, 41), validation = test::noisy_toy(200, 42);
  BoostTrainingParams params;
  params.rounds = 10;
  params.bins.count = 8;  // few samples: coarse bins generalise
  const BoostedModel model = train_boosted_model(train.rows, train.labels, params, {}, &validation.rows,
                                                 &validation.labels);
  EXPECT_EQ(model.training().validation.source, "separate sets");
  EXPECT_EQ(model.training().train_positives + model.training().train_negatives, 400u);
  EXPECT_GT(model.training().validation.summary.auc, 0.75);
  EXPECT_EQ(model.training().validation.rounds.size(), 1u);  // round 10
  params.backend = "xgboost";
  EXPECT_THROW(train_boosted_model(train.rows, train.labels, params), Error);
  params.backend = "native";
  params.rounds = 0;
  EXPECT_THROW(train_boosted_model(train.rows, train.labels, params), Error);
  params.rounds = 3;
  EXPECT_THROW(train_boosted_model(train.rows.colRange(0, 100).clone(), train.labels, params), Error);
  params.validation_fraction = 0.0;
  params.early_stopping = 5;  // nothing to stop on
  EXPECT_THROW(train_boosted_model(train.rows, train.labels, params), Error);
  params.early_stopping = 0;
  EXPECT_EQ(train_boosted_model(train.rows, train.labels, params).training().validation.source, "none");
}

TEST(OpenCvBackend, StumpsReproducePredictSumAndLearnTheToy) {
  const test::ToyData toy = test::noisy_toy(240, 51);
  OpenCvBoostParams params;
  params.rounds = 4;
  const OpenCvBoostResult result = train_opencv_boost(toy.rows, toy.labels, params);
  ASSERT_EQ(result.stumps.size(), 4u);
  const std::vector<double> reference = opencv_boost_scores(result.yaml, toy.rows);
  const BoostedModel model(FeatureSpec{}, BinScheme{}, result.stumps);
  const std::vector<double> ours = model.score(toy.rows);
  ASSERT_EQ(ours.size(), reference.size());
  for (std::size_t i = 0; i < ours.size(); ++i) EXPECT_NEAR(ours[i], reference[i], 1e-4) << i;
  EXPECT_GT(roc_auc(ours, toy.labels), 0.75);
  std::set<int> features;
  for (const WeakClassifier& w : result.stumps) features.insert(w.feature);
  EXPECT_TRUE(features.count(10) + features.count(2000) + features.count(5000) > 0);
}

TEST(OpenCvBackend, TrainedThroughTheCommonPathWithEmbeddedModel) {
  const test::ToyData toy = test::separable_toy(200, 4321, 61);
  BoostTrainingParams params;
  params.backend = "opencv";
  params.rounds = 2;
  const BoostedModel model = train_boosted_model(toy.rows, toy.labels, params);
  ASSERT_EQ(model.weak_classifiers().size(), 2u);
  EXPECT_EQ(model.weak_classifiers().front().kind, WeakClassifier::Kind::Stump);
  EXPECT_EQ(model.weak_classifiers().front().feature, 4321);
  EXPECT_FALSE(model.opencv_model_yaml().empty());
  EXPECT_DOUBLE_EQ(model.training().validation.summary.auc, 1.0);
  const std::vector<double> reference = opencv_boost_scores(model.opencv_model_yaml(), toy.rows);
  const std::vector<double> ours = model.score(toy.rows);
  for (std::size_t i = 0; i < ours.size(); ++i) EXPECT_NEAR(ours[i], reference[i], 1e-4) << i;
}

}  // namespace
}  // namespace rdsf
