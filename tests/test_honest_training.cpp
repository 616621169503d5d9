// The levers of honest figures and generalisation: validation split by group, Platt calibration, the exact
// detection curve, training-time augmentation, trees of look-up tables and shrinkage, format 2 model files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <random>
#include <set>

#include "rdsf/classifier/binned_matrix.hpp"
#include "rdsf/classifier/features_read.hpp"
#include "rdsf/classifier/boost_training.hpp"
#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/classifier/model_file.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/classifier/platt_calibration.hpp"
#include "rdsf/classifier/real_adaboost.hpp"
#include "rdsf/classifier/seeded_sampling.hpp"
#include "rdsf/dataset/crop_augmentation.hpp"
#include "rdsf/dataset/sample_groups.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/evaluation/detection_metrics.hpp"
#include "rdsf/evaluation/exact_curve.hpp"
#include "rdsf/evaluation/threshold_sweep.hpp"
#include "support/test_support.hpp"

namespace rdsf {
namespace {

namespace fs = std::filesystem;

std::string message_of(const std::function<void()>& f) { return test::error_message(f); }

// ---- group split ----

// A sample set as the labeller and the miner write them: two recordings, several samples per frame of
// both labels, frames named as recordings name them.
TEST(GroupSplit, NeverPutsOneGroupOnBothSidesOfASampleSet) {
  const test::TempDir dir("rdsf-groups");
  const std::string path = (dir.path() / "set").string();
  {
    SampleSetWriter writer = SampleSetWriter::open_or_create(path, FeatureSpec{}, CameraModel{}, "test");
    std::mt19937_64 rng(3);
    for (const char* source : {"data/train", "/abs/data/empty/"}) {
      for (int frame = 0; frame < 240; ++frame) {
        for (int k = 0; k < 3; ++k) {
          SampleRecord r;
          r.label = (k == 0 && std::string(source) == "data/train") ? 1 : 0;
          r.origin = "test";
          r.source = source;
          char name[16];
          std::snprintf(name, sizeof name, "%06d", frame);
          r.frame = name;
          r.strict_box = cv::Rect(k * 20, 0, 10, 20);
          r.window = r.strict_box;
          cv::Mat1w crop(128, 64, static_cast<std::uint16_t>(1000 + rng() % 3000));
          writer.append(r, crop);
        }
      }
    }
  }
  const SampleSet set = SampleSet::open_read(path);
  std::vector<SampleOrigin> origins;
  std::vector<int> labels;
  for (const SampleRecord& r : set.records()) {
    origins.push_back({r.source, r.frame});
    labels.push_back(r.label);
  }
  const SampleGroups groups = sample_groups(origins, 30);
  EXPECT_EQ(groups.names.size(), 16u);  // two recordings x 240 frames / 30
  EXPECT_EQ(recording_of("/abs/data/empty/"), "empty");
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const HoldOutSplit split = group_split(labels, groups.group, 0.2, seed);
    std::set<std::pair<std::string, std::string>> train_frames, validation_frames;
    for (std::size_t i : split.train) train_frames.insert({recording_of(origins[i].source), origins[i].frame});
    for (std::size_t i : split.validation) validation_frames.insert({recording_of(origins[i].source), origins[i].frame});
    for (const auto& f : validation_frames) EXPECT_EQ(train_frames.count(f), 0u) << f.first << " " << f.second;
    // Neighbouring frames stay together: a held-out frame's neighbour is held out unless it starts a block.
    for (std::size_t i : split.validation) {
      const int frame = std::stoi(origins[i].frame);
      if (frame % 30 == 29) continue;
      char next[16];
      std::snprintf(next, sizeof next, "%06d", frame + 1);
      EXPECT_EQ(train_frames.count({recording_of(origins[i].source), next}), 0u);
    }
    const auto val_pos = std::count_if(split.validation.begin(), split.validation.end(), [&](std::size_t i) { return labels[i] == 1; });
    EXPECT_GT(val_pos, 0);
    EXPECT_LT(val_pos, 240);
    EXPECT_EQ(split.train.size() + split.validation.size(), labels.size());
  }
}

TEST(GroupSplit, KeepsEachClassNearItsFractionAndRefusesAnEmptyClass) {
  std::mt19937_64 rng(7);
  std::vector<int> labels;
  std::vector<std::size_t> group;
  for (std::size_t g = 0; g < 200; ++g) {
    const int n = 5 + static_cast<int>(rng() % 20);
    for (int k = 0; k < n; ++k) {
      labels.push_back(rng() % 3 == 0 ? 1 : 0);
      group.push_back(g * 7919);  // any numbers
    }
  }
  const HoldOutSplit split = group_split(labels, group, 0.25, 11);
  const double pos = static_cast<double>(std::count(labels.begin(), labels.end(), 1));
  double val_pos = 0, val_all = 0;
  for (std::size_t i : split.validation) {
    val_pos += labels[i];
    val_all += 1;
  }
  EXPECT_NEAR(val_pos / pos, 0.25, 0.05);
  EXPECT_NEAR(val_all / static_cast<double>(labels.size()), 0.25, 0.05);
  // Every positive in one group: the split cannot leave positives on both sides.
  std::vector<int> one = {1, 1, 1, 0, 0, 0, 0};
  std::vector<std::size_t> g1 = {0, 0, 0, 1, 2, 3, 4};
  EXPECT_NE(message_of([&] { group_split(one, g1, 0.3, 1); }).find("leaves a class empty"), std::string::npos);
  // Augmented copies follow their group and do not count.
  std::vector<bool> counts(labels.size(), true);
  for (std::size_t i = 0; i < counts.size(); i += 2) counts[i] = false;
  const HoldOutSplit with_copies = group_split(labels, group, 0.25, 11, counts);
  std::set<std::size_t> held;
  for (std::size_t i : with_copies.validation) held.insert(group[i]);
  for (std::size_t i : with_copies.train) EXPECT_EQ(held.count(group[i]), 0u);
}

// ---- calibration ----

// Scores whose true log-odds are 1.5 s - 0.5: Platt scaling must recover them, and the probabilities it
// gives must match the observed frequencies on other samples of the same problem (within 0.03 per bin of
// at least 500 samples).
TEST(Calibration, PlattMapsHeldOutScoresToFrequencies) {
  auto draw = [](std::uint64_t seed, std::size_t n, std::vector<double>& s, std::vector<int>& y) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> score(-4.0, 4.0), u(0.0, 1.0);
    for (std::size_t i = 0; i < n; ++i) {
      s.push_back(score(rng));
      y.push_back(u(rng) < 1.0 / (1.0 + std::exp(-(1.5 * s.back() - 0.5))) ? 1 : 0);
    }
  };
  std::vector<double> fit_s, test_s;
  std::vector<int> fit_y, test_y;
  draw(1, 20000, fit_s, fit_y);
  draw(2, 50000, test_s, test_y);
  const ScoreCalibration c = fit_platt(fit_s, fit_y);
  EXPECT_EQ(c.method, "platt");
  EXPECT_NEAR(c.a, 1.5, 0.1);
  EXPECT_NEAR(c.b, -0.5, 0.1);
  std::vector<double> sum_p(10, 0.0), hits(10, 0.0), count(10, 0.0);
  for (std::size_t i = 0; i < test_s.size(); ++i) {
    const double p = c.probability(test_s[i]);
    const auto bin = std::min<std::size_t>(9, static_cast<std::size_t>(p * 10));
    sum_p[bin] += p;
    hits[bin] += test_y[i];
    count[bin] += 1;
  }
  int checked = 0;
  for (std::size_t b = 0; b < 10; ++b) {
    if (count[b] < 500) continue;
    EXPECT_NEAR(hits[b] / count[b], sum_p[b] / count[b], 0.03) << "bin " << b;
    ++checked;
  }
  EXPECT_GE(checked, 8);
  EXPECT_NEAR(c.probability(c.score_at(0.8)), 0.8, 1e-12);
  // Perfectly separated scores still give finite numbers.
  const ScoreCalibration sep = fit_platt({-3, -2, -1, 1, 2, 3}, {0, 0, 0, 1, 1, 1});
  EXPECT_TRUE(std::isfinite(sep.a) && std::isfinite(sep.b));
  EXPECT_GT(sep.a, 0.0);
  EXPECT_NE(message_of([] { fit_platt({1, 2}, {1, 1}); }).find("both classes"), std::string::npos);
  // Without calibration P is Real AdaBoost's reading of H as half the log-odds.
  EXPECT_NEAR(ScoreCalibration{}.probability(0.5), 1.0 / (1.0 + std::exp(-1.0)), 1e-15);
}

// ---- exact curve ----

// The TAR read off the exact curve at an FPPF limit, and its 95 % interval over the people at that point.
TEST(ExactCurve, TarAtAnFppfLimitAndItsIntervalOverThePeople) {
  SweepResult r;
  auto point = [](double fppf, long found, long people) {
    DetectionFigures f;
    f.fppf = fppf;
    f.n_det = found;
    f.n_people = people;
    f.tar = static_cast<double>(found) / static_cast<double>(people);
    return f;
  };
  r.curve = {point(0.05, 30, 50), point(0.2, 40, 50), point(0.08, 25, 50), point(0.6, 45, 50)};
  EXPECT_DOUBLE_EQ(r.tar_at_fppf(0.1), 0.6);
  const RateInterval at01 = r.tar_interval_at_fppf(0.1), expected01 = wilson_interval(30, 50);
  EXPECT_DOUBLE_EQ(at01.low, expected01.low);
  EXPECT_DOUBLE_EQ(at01.high, expected01.high);
  EXPECT_LT(at01.low, 0.6);
  EXPECT_GT(at01.high, 0.6);
  const RateInterval at05 = r.tar_interval_at_fppf(0.5), expected05 = wilson_interval(40, 50);
  EXPECT_DOUBLE_EQ(at05.low, expected05.low);
  EXPECT_DOUBLE_EQ(at05.high, expected05.high);
  const RateInterval none = r.tar_interval_at_fppf(0.01);  // no point qualifies
  EXPECT_EQ(none.low, 0.0);
  EXPECT_EQ(none.high, 1.0);
}

TEST(ExactCurve, EqualsABruteForceCountAtEveryDistinctScore) {
  std::mt19937_64 rng(5);
  GroundTruth truth;
  std::vector<FrameCandidates> frames;
  for (int f = 0; f < 60; ++f) {
    FrameCandidates fc{"f" + std::to_string(f), {}};
    const int people = static_cast<int>(rng() % 4);
    for (int p = 0; p < people; ++p) {
      TruthBox t;
      t.box = cv::Rect(static_cast<int>(rng() % 400), static_cast<int>(rng() % 200), 60, 150);
      t.track = p;
      t.ignored = rng() % 6 == 0;
      truth.frames[fc.frame].push_back(t);
      // Candidates near the person: good, shifted, duplicate.
      for (int k = 0; k < 3; ++k) {
        const int dx = static_cast<int>(rng() % 40) - 20;
        // Kin: the three may be a whole and its pieces (duplicates) or of no object.
        const CandidateKin kin{static_cast<int>(rng() % 3) - 1, rng() % 2 == 0};
        fc.candidates.push_back({t.box + cv::Point(dx, 0), static_cast<double>(rng() % 20) / 4.0, kin});  // ties
      }
    }
    for (int k = 0; k < 4; ++k) {
      fc.candidates.push_back({cv::Rect(static_cast<int>(rng() % 500), 300, 50, 100), static_cast<double>(rng() % 20) / 4.0, {}});
    }
    frames.push_back(fc);
  }
  for (bool clean : {false, true}) {
    const std::vector<DetectionFigures> curve = exact_detection_curve(frames, truth, clean);
    std::set<double> distinct;
    for (const FrameCandidates& f : frames) {
      for (const ScoredCandidate& c : f.candidates) distinct.insert(c.score);
    }
    ASSERT_EQ(curve.size(), distinct.size());
    for (const DetectionFigures& point : curve) {
      const DetectionFigures brute = detection_figures(frames, truth, point.threshold, clean);
      if (!clean) {
        // Only the candidates scoring >= the threshold, as a detector at that threshold sees them: the same
        // duplicates, so the same figures (duplicate_candidates.hpp's invariant).
        std::vector<FrameCandidates> passing;
        for (const FrameCandidates& f : frames) {
          FrameCandidates kept{f.frame, {}};
          for (const ScoredCandidate& c : f.candidates) {
            if (c.score >= point.threshold) kept.candidates.push_back(c);
          }
          passing.push_back(kept);
        }
        const DetectionFigures alone = detection_figures(passing, truth, point.threshold, false);
        EXPECT_EQ(point.n_det, alone.n_det) << point.threshold;
        EXPECT_EQ(point.n_fp, alone.n_fp) << point.threshold;
      }
      EXPECT_EQ(point.n_det, brute.n_det) << point.threshold;
      EXPECT_EQ(point.n_fp, brute.n_fp) << point.threshold;
      EXPECT_EQ(point.n_miss, brute.n_miss) << point.threshold;
      EXPECT_EQ(point.n_people, brute.n_people);
      EXPECT_DOUBLE_EQ(point.tar, brute.tar);
      EXPECT_DOUBLE_EQ(point.fppf, brute.fppf);
    }
    EXPECT_TRUE(std::is_sorted(curve.begin(), curve.end(),
                               [](const DetectionFigures& a, const DetectionFigures& b) { return a.threshold > b.threshold; }));
  }
}

// ---- augmentation ----

cv::Mat1w hand_built_crop() {
  cv::Mat1w crop(128, 64, std::uint16_t{0});
  for (int y = 0; y < 128; ++y) {
    for (int x = 0; x < 64; ++x) {
      if (x < 20 && y > 10) crop(y, x) = static_cast<std::uint16_t>(1000 + x * 10 + y);
    }
  }
  return crop;
}

TEST(Augmentation, MirrorsAHandBuiltCropExactlyAndShiftsAsStated) {
  const cv::Mat1w crop = hand_built_crop();
  const cv::Mat1w m = mirrored_crop(crop);
  for (int y = 0; y < 128; ++y) {
    for (int x = 0; x < 64; ++x) ASSERT_EQ(m(y, x), crop(y, 63 - x)) << x << "," << y;
  }
  EXPECT_EQ(m(50, 63), 1000 + 0 * 10 + 50);
  EXPECT_EQ(cv::countNonZero(mirrored_crop(m) != crop), 0);
  const cv::Mat1w shifted = shifted_scaled_crop(crop, 3, -2, 1.0);
  EXPECT_EQ(shifted(50, 3), crop(52, 0));
  EXPECT_EQ(shifted(50, 0), 0);  // came from outside the crop
  EXPECT_EQ(cv::countNonZero(shifted_scaled_crop(crop, 0, 0, 1.0) != crop), 0);
  const cv::Mat1w occluded = occluded_crop(crop, cv::Rect(0, 100, 64, 40));
  EXPECT_EQ(cv::countNonZero(occluded.rowRange(100, 128)), 0);
  EXPECT_EQ(cv::countNonZero(occluded.rowRange(0, 100) != crop.rowRange(0, 100)), 0);
}

TEST(Augmentation, IsDeterministicForASeedAndRefusesLeavingTheWindow) {
  const cv::Mat1w crop = hand_built_crop();
  const CropAugmentation a = parse_augmentation("mirror,shift,scale,occlusion", 3, 42);
  const std::vector<cv::Mat1w> one = augmented_crops(crop, a, 7), two = augmented_crops(crop, a, 7);
  ASSERT_EQ(one.size(), 4u);  // the mirror and three copies
  for (std::size_t k = 0; k < one.size(); ++k) EXPECT_EQ(cv::countNonZero(one[k] != two[k]), 0);
  EXPECT_EQ(cv::countNonZero(one[0] != mirrored_crop(crop)), 0);
  const std::vector<cv::Mat1w> other = augmented_crops(crop, a, 8);
  bool differs = false;
  for (std::size_t k = 1; k < one.size(); ++k) differs = differs || cv::countNonZero(one[k] != other[k]) > 0;
  EXPECT_TRUE(differs);
  CropAugmentation far = a;
  far.max_shift = 0.3;
  EXPECT_NE(message_of([&] { far.validate(); }).find("out of it"), std::string::npos);
  EXPECT_NE(message_of([] { parse_augmentation("mirror,rotate", 0, 1); }).find("'rotate' is not known"), std::string::npos);
  EXPECT_NE(message_of([] { parse_augmentation("mirror", 2, 1); }).find("need shift"), std::string::npos);
  EXPECT_EQ(parse_augmentation("off", 0, 1).describe(), "off");
}

// ---- trees and shrinkage ----

// A person when two features are both high: one look-up table sees only one of them, a depth-2 tree both.
void and_problem(cv::Mat1f& rows, std::vector<int>& labels) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  rows.create(800, 8128);
  for (int r = 0; r < rows.rows; ++r) {
    for (int c = 0; c < rows.cols; ++c) rows(r, c) = u(rng);
    labels.push_back((rows(r, 100) > 0.5f && rows(r, 200) > 0.5f) ? 1 : 0);
  }
}

// The problem in the trainer's sample order (positives first).
struct OrderedProblem {
  cv::Mat1f rows;
  std::vector<int> labels, ordered;
  std::vector<std::size_t> order;
  OrderedProblem() {
    and_problem(rows, labels);
    order = positives_first_order(labels);
    for (std::size_t i : order) ordered.push_back(labels[i]);
  }
};

TEST(Trees, ADepthTwoTreeLearnsWhatOneTableCannot) {
  const OrderedProblem problem;
  const cv::Mat1f& rows = problem.rows;
  const std::vector<std::size_t>& order = problem.order;
  const std::vector<int>& ordered = problem.ordered;
  BinScheme bins;
  bins.count = 16;
  const BinnedMatrix data(rows, bins, order, 1);
  RealAdaBoostParams flat;
  RealAdaBoost table(data, ordered, flat);
  const double table_error = table.next_round().train_error;
  RealAdaBoostParams deep;
  deep.depth = 2;
  RealAdaBoost tree(data, ordered, deep);
  const RealAdaBoostRound r = tree.next_round();
  EXPECT_GT(table_error, 0.1);
  EXPECT_LT(r.train_error, 0.02);
  const WeakClassifier& w = tree.weak_classifiers().front();
  ASSERT_EQ(w.kind, WeakClassifier::Kind::Tree);
  ASSERT_EQ(w.nodes.size(), 3u);
  EXPECT_EQ(w.depth(), 2);
  const std::vector<int> features = w.features_read();  // one vector: begin and end of the same one
  const std::set<int> read(features.begin(), features.end());
  EXPECT_TRUE(read.count(100) == 1 && read.count(200) == 1);
  // The same tree whatever the thread count.
  deep.threads = 2;
  RealAdaBoost two(data, ordered, deep);
  two.next_round();
  EXPECT_TRUE(two.weak_classifiers().front() == w);
  // Scoring a row through the tree gives the training score.
  BoostedModel model(FeatureSpec{}, bins, tree.weak_classifiers());
  for (std::size_t s = 0; s < 20; ++s) {
    EXPECT_DOUBLE_EQ(model.score(rows[static_cast<int>(order[s])]), tree.train_scores()[s]);
  }
}

TEST(Trees, LearningRateScalesEveryResponse) {
  const OrderedProblem problem;
  const std::vector<int>& ordered = problem.ordered;
  const BinnedMatrix data(problem.rows, BinScheme{}, problem.order, 1);
  RealAdaBoostParams full, half;
  half.learning_rate = 0.5;
  RealAdaBoost a(data, ordered, full), b(data, ordered, half);
  a.next_round();
  b.next_round();
  const WeakClassifier &wa = a.weak_classifiers()[0], &wb = b.weak_classifiers()[0];
  ASSERT_EQ(wa.feature, wb.feature);
  for (std::size_t j = 0; j < wa.responses.size(); ++j) EXPECT_DOUBLE_EQ(wb.responses[j], 0.5 * wa.responses[j]);
  RealAdaBoostParams bad;
  bad.depth = 5;
  EXPECT_NE(message_of([&] { RealAdaBoost(data, ordered, bad); }).find("depth 5"), std::string::npos);
}

// ---- training with groups, calibration and format 2 ----

TEST(HonestTraining, GroupValidationCalibratesAndSavesFormatTwo) {
  cv::Mat1f rows;
  std::vector<int> labels;
  and_problem(rows, labels);
  TrainingRowInfo info;
  for (int r = 0; r < rows.rows; ++r) info.groups.push_back(static_cast<std::size_t>(r / 10));
  BoostTrainingParams p;
  p.rounds = 6;
  p.depth = 2;
  p.learning_rate = 0.5;
  p.bins.count = 16;
  p.folds = 0;  // one held-out fraction of the groups
  BoostedModel model = train_boosted_model(rows, labels, p, {}, nullptr, nullptr, info);
  const ValidationFigures& v = model.training().validation;
  EXPECT_NE(v.source.find("held-out groups"), std::string::npos) << v.source;
  EXPECT_EQ(model.calibration().method, "platt");
  EXPECT_GT(model.calibration().a, 0.0);
  ASSERT_EQ(v.by_probability.size(), 19u);
  EXPECT_NEAR(v.by_probability[9].probability, 0.5, 1e-12);
  EXPECT_GT(v.summary.auc, 0.9);
  const test::TempDir dir("rdsf-format2");
  const std::string path = save_new_model_version(model, "and", dir.path().string());
  const BoostedModel back = BoostedModel::load(path);
  EXPECT_EQ(back.format_version(), kModelFormatVersion);
  EXPECT_EQ(back.calibration().method, "platt");
  EXPECT_DOUBLE_EQ(back.calibration().a, model.calibration().a);
  ASSERT_EQ(back.weak_classifiers().size(), model.weak_classifiers().size());
  EXPECT_TRUE(back.weak_classifiers().front() == model.weak_classifiers().front());
  for (int r = 0; r < 30; ++r) {
    EXPECT_DOUBLE_EQ(back.score(rows[r]), model.score(rows[r]));
    EXPECT_DOUBLE_EQ(back.probability(back.score(rows[r])), model.probability(model.score(rows[r])));
  }
  EXPECT_EQ(back.training().validation.by_probability.size(), 19u);
  // Refusals before any work.
  BoostTrainingParams wrong = p;
  wrong.calibration = "isotonic";
  EXPECT_NE(message_of([&] { validate_training_params(wrong); }).find("'isotonic' is not known"), std::string::npos);
  wrong = p;
  wrong.learning_rate = 0.0;
  EXPECT_NE(message_of([&] { validate_training_params(wrong); }).find("learning-rate must be in (0, 1]"), std::string::npos);
}

// K-fold by group: every original row is validated once, by a model that never saw its group; the final
// model is the one trained on everything.
TEST(HonestTraining, GroupFoldsValidateEveryRowOnceAndKeepTheFullModel) {
  cv::Mat1f rows;
  std::vector<int> labels;
  and_problem(rows, labels);
  TrainingRowInfo info;
  for (int r = 0; r < rows.rows; ++r) {
    info.groups.push_back(static_cast<std::size_t>(r / 20));
    info.augmented.push_back(r % 10 == 9);  // pretend every tenth row is a copy
  }
  BoostTrainingParams p;
  p.rounds = 5;
  p.depth = 2;
  p.bins.count = 16;
  p.folds = 4;
  p.report_every = 1;
  const BoostedModel model = train_boosted_model(rows, labels, p, {}, nullptr, nullptr, info);
  const ValidationFigures& v = model.training().validation;
  EXPECT_NE(v.source.find("4 folds of whole groups (40 groups"), std::string::npos) << v.source;
  EXPECT_EQ(v.positives + v.negatives, 720u);  // the 800 rows less the 80 copies
  EXPECT_EQ(v.rounds.size(), 5u);
  EXPECT_EQ(v.by_probability.size(), 19u);
  EXPECT_EQ(model.calibration().method, "platt");
  BoostTrainingParams all = p;
  all.folds = 0;
  all.validation_fraction = 0;
  const BoostedModel full = train_boosted_model(rows, labels, all);
  ASSERT_EQ(full.weak_classifiers().size(), model.weak_classifiers().size());
  for (std::size_t k = 0; k < full.weak_classifiers().size(); ++k) {
    EXPECT_TRUE(full.weak_classifiers()[k] == model.weak_classifiers()[k]) << k;
  }
  BoostTrainingParams bad = p;
  bad.folds = 60;
  EXPECT_NE(message_of([&] { train_boosted_model(rows, labels, bad, {}, nullptr, nullptr, info); }).find("folds must be"),
            std::string::npos);
}

// ---- continued training (rdsf-train --init) ----

// Real AdaBoost's weights after t rounds are exp(-y F_t) normalised, so continuing a 4-round model for 4
// more rounds on the same rows chooses what an 8-round training chooses, and scores as it does.
TEST(ContinuedTraining, ContinuingAModelEqualsTrainingItLonger) {
  cv::Mat1f rows;
  std::vector<int> labels;
  and_problem(rows, labels);
  BoostTrainingParams p;
  p.depth = 2;
  p.bins.count = 16;
  p.folds = 0;
  p.validation_fraction = 0;
  p.rounds = 4;
  const BoostedModel first = train_boosted_model(rows, labels, p);
  p.rounds = 8;
  const BoostedModel longer = train_boosted_model(rows, labels, p);
  BoostTrainingParams more = p;
  more.rounds = 4;
  more.init = first.weak_classifiers();
  const BoostedModel continued = train_boosted_model(rows, labels, more);
  ASSERT_EQ(continued.weak_classifiers().size(), 8u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_TRUE(continued.weak_classifiers()[k] == first.weak_classifiers()[k]) << k;
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_EQ(continued.weak_classifiers()[k].feature, longer.weak_classifiers()[k].feature) << k;
  }
  const std::vector<double> a = continued.score(rows), b = longer.score(rows);
  for (int r = 0; r < rows.rows; ++r) ASSERT_NEAR(a[static_cast<std::size_t>(r)], b[static_cast<std::size_t>(r)], 1e-6) << r;
  EXPECT_NE(std::find(continued.training().parameters.begin(), continued.training().parameters.end(),
                      std::make_pair(std::string("init_weak_classifiers"), std::string("4"))),
            continued.training().parameters.end());

  // With group folds every fold's model starts from the same weak classifiers; the figures are the new
  // rounds' and the kept model holds both.
  TrainingRowInfo info;
  for (int r = 0; r < rows.rows; ++r) info.groups.push_back(static_cast<std::size_t>(r / 20));
  BoostTrainingParams folds = more;
  folds.folds = 4;
  folds.report_every = 1;
  const BoostedModel folded = train_boosted_model(rows, labels, folds, {}, nullptr, nullptr, info);
  ASSERT_EQ(folded.weak_classifiers().size(), 8u);
  EXPECT_TRUE(folded.weak_classifiers()[0] == first.weak_classifiers()[0]);
  EXPECT_EQ(folded.training().validation.rounds.size(), 4u);
  EXPECT_GT(folded.training().validation.summary.auc, 0.9);

  BoostTrainingParams opencv = more;
  opencv.backend = BoostBackend::opencv;
  EXPECT_NE(message_of([&] { train_boosted_model(rows, labels, opencv); }).find("needs the native backend"),
            std::string::npos);

  // Rows of a feature pool that holds every feature the longer training reads (the init's among them):
  // continuing on them chooses the same, and the model names the spec's features, not the pool's columns.
  BoostTrainingParams pool = more;
  pool.feature_columns = features_read(longer);
  const auto pool_rows = [&rows](const std::vector<int>& columns) {
    cv::Mat1f out(rows.rows, static_cast<int>(columns.size()));
    for (std::size_t c = 0; c < columns.size(); ++c) rows.col(columns[c]).copyTo(out.col(static_cast<int>(c)));
    return out;
  };
  ASSERT_LT(pool.feature_columns.size(), 40u);
  const BoostedModel pooled = train_boosted_model(pool_rows(pool.feature_columns), labels, pool);
  ASSERT_EQ(pooled.weak_classifiers().size(), 8u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_TRUE(pooled.weak_classifiers()[k] == first.weak_classifiers()[k]) << k;
  const std::vector<double> c = pooled.score(rows);
  for (int r = 0; r < rows.rows; ++r) ASSERT_NEAR(c[static_cast<std::size_t>(r)], b[static_cast<std::size_t>(r)], 1e-6) << r;

  // A pool without a feature the init model reads is refused.
  const int needed = features_read(first).front();
  pool.feature_columns.erase(std::find(pool.feature_columns.begin(), pool.feature_columns.end(), needed));
  EXPECT_NE(message_of([&] { train_boosted_model(pool_rows(pool.feature_columns), labels, pool); })
                .find("reads feature " + std::to_string(needed) + ", which the rows' feature pool does not hold"),
            std::string::npos);
}

}  // namespace
}  // namespace rdsf
