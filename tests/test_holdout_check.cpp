// rdsf-adapt's held-out check (pipeline/holdout_check.hpp): the later half of a room's frames, the people a
// model finds at FPPF <= 0.1 among labelled candidates, the detector's scores of stored crops, the model as
// given made a room's model, and a merge that keeps the earlier frames' samples only.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_merge.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/pipeline/holdout_check.hpp"
#include "rdsf/pipeline/model_scorer.hpp"
#include "support/depth_scenes.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

// A person-like masked crop with an arm held out on one side: not its own mirror.
cv::Mat1w leaning_crop(unsigned seed) {
  cv::Mat1w crop = test::person_crop(seed);
  crop(cv::Rect(40, 30, 12, 40)).setTo(2500);
  return crop;
}

BoostedModel shipped() { return BoostedModel::load("people", std::string(RDSF_SOURCE_DIR) + "/models"); }

}  // namespace

TEST(HoldoutCheck, TheLaterHalfIsTheLastFramesAndTheMiddleOneOfAnOddCountGoesToIt) {
  EXPECT_EQ(later_half({"a", "b", "c", "d"}), (std::vector<std::string>{"c", "d"}));
  EXPECT_EQ(later_half({"a", "b", "c"}), (std::vector<std::string>{"b", "c"}));
  EXPECT_TRUE(later_half({}).empty());
}

// At FPPF <= 0.1 over 20 frames two other candidates may pass: the threshold must pass above the third highest.
TEST(HoldoutCheck, PeopleFoundAreThoseAboveTheHighestOtherCandidateTheFalsePositiveBudgetCannotTake) {
  const std::vector<double> people{0.9, 0.5, 0.31, 0.3, -1.0};
  EXPECT_EQ(people_found_at_fppf(people, {0.8, 0.7, 0.3, 0.2}, 20, 0.1), 3u);  // above 0.3: 0.9, 0.5, 0.31
  EXPECT_EQ(people_found_at_fppf(people, {0.8, 0.7, 0.3, 0.2}, 30, 0.1), 4u);  // three may pass: above 0.2
  EXPECT_EQ(people_found_at_fppf(people, {0.8, 0.7}, 20, 0.1), 5u);            // no more others than the budget
  EXPECT_EQ(people_found_at_fppf(people, {0.95}, 9, 0.1), 0u);                 // 9 frames: no false positive
  EXPECT_EQ(people_found_at_fppf(people, {0.5, 0.5, 0.5}, 20, 0.1), 1u);       // a tie cannot be cut: above it
  EXPECT_EQ(people_found_at_fppf({}, {0.1}, 5, 0.1), 0u);
  EXPECT_THROW(people_found_at_fppf(people, {}, 0, 0.1), Error);
}

// Who becomes the room's model: the trial on a tie with the model as given; with switches taken, the model as
// given without them only when it finds more people than both (a tie keeps the others' decision).
TEST(HoldoutCheck, TheModelWithoutTheSwitchesWinsOnlyWhenItFindsMoreThanBoth) {
  HoldoutFigures f;
  f.base_found = 4;
  f.trial_found = 4;
  EXPECT_TRUE(f.trial_kept());
  EXPECT_FALSE(f.as_given_kept());
  f.as_given_found = 4;  // a tie with both: the trial
  EXPECT_TRUE(f.trial_kept());
  EXPECT_FALSE(f.as_given_kept());
  f.as_given_found = 5;
  EXPECT_TRUE(f.as_given_kept());
  EXPECT_FALSE(f.trial_kept());
  f.trial_found = 5;  // the trial as good: it stays
  EXPECT_FALSE(f.as_given_kept());
  EXPECT_TRUE(f.trial_kept());
  f.trial_found = 3;
  f.as_given_found = 4;  // the base stating the switches wins over the trial; as given only ties with it
  EXPECT_FALSE(f.as_given_kept());
  EXPECT_FALSE(f.trial_kept());
}

// The detector's score of a stored crop: the shipped model is mirror-averaged whole; the model as given made a
// room's model scores every crop the same, bit for bit, while it says it was adapted and states the options.
TEST(HoldoutCheck, TheModelAsGivenKeptForTheRoomScoresAsTheModelAsGiven) {
  const BoostedModel base = shipped();
  ASSERT_FALSE(base.training().adapted_to_a_room());
  std::vector<cv::Mat1w> crops;
  for (unsigned seed = 0; seed < 6; ++seed) crops.push_back(leaning_crop(seed));
  const PipelineParams params;
  const std::vector<double> scores = detector_scores(base, params, crops);
  const ModelScorer scorer(base);
  int mirror_differs = 0;
  for (std::size_t i = 0; i < crops.size(); ++i) {
    EXPECT_EQ(scores[i], 0.5 * (scorer.score(crops[i]) + scorer.mirrored_score(crops[i])));
    mirror_differs += scorer.score(crops[i]) != scorer.mirrored_score(crops[i]) ? 1 : 0;
  }
  EXPECT_GT(mirror_differs, 0);  // the averaging is not the identity on these crops
  RecordedParameters options = base.detection_options();
  ASSERT_FALSE(options.empty());
  for (auto& [key, text] : options) {
    if (key == "hole_gap") text = "20";
  }
  const BoostedModel kept = base_as_room_model(base, options, {{kAdaptedRoomParameter, "/rooms/lab"}, {"adapted_check", "x"}});
  EXPECT_TRUE(kept.training().adapted_to_a_room());
  EXPECT_EQ(kept.training().inherited_weak_classifiers(), base.weak_classifiers().size());
  EXPECT_EQ(kept.detection_options(), options);
  EXPECT_NE(kept.detection_options(), base.detection_options());
  EXPECT_EQ(detector_scores(kept, params, crops), scores);
  // Made a room's model without the inherited count, the same weights would be scored on the crop alone.
  BoostedModel unmarked = kept;
  auto& parameters = unmarked.training().parameters;
  for (auto& [key, value] : parameters) {
    if (key == kInitWeakClassifiersParameter) value = "0";
  }
  EXPECT_NE(detector_scores(unmarked, params, crops), scores);
}

// The trial's sets: the samples of the earlier frames copied, those of the later half left out.
TEST(HoldoutCheck, AMergeKeepsOnlyTheSamplesItIsToldTo) {
  test::TempDir dir;
  {
    SampleSetWriter in = SampleSetWriter::open_or_create(dir / "in", FeatureSpec{}, CameraModel::kinect_v1(), "test");
    for (int f = 0; f < 6; ++f) {
      SampleRecord r;
      r.label = f % 2;
      r.origin = "labeler";
      r.source = "room";
      r.frame = "00000" + std::to_string(f);
      r.strict_box = r.window = cv::Rect(10 * f, 10, 40, 80);
      in.append(r, leaning_crop(static_cast<unsigned>(f)));
    }
  }
  const std::vector<std::string> later = later_half({"000000", "000001", "000002", "000003", "000004", "000005"});
  SampleSetWriter out = SampleSetWriter::open_or_create(dir / "out", FeatureSpec{}, CameraModel::kinect_v1(), "test");
  const MergeResult merged = merge_sample_sets({dir / "in"}, out, [&](const SampleRecord& r) {
    return std::find(later.begin(), later.end(), r.frame) == later.end();
  });
  out.sync();
  EXPECT_EQ(merged.added, 3);
  const SampleSet kept = SampleSet::open_read(dir / "out");
  ASSERT_EQ(kept.records().size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(kept.records()[i].frame, "00000" + std::to_string(i));
    EXPECT_EQ(cv::norm(kept.depth_crop(i), leaning_crop(static_cast<unsigned>(i)), cv::NORM_INF), 0.0);
  }
}
