// Figures and intervals by clip (rdsf/evaluation/clip_bootstrap.hpp), on hand-built frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "rdsf/core/error.hpp"
#include "rdsf/evaluation/clip_bootstrap.hpp"
#include "rdsf/evaluation/exact_curve.hpp"

namespace {

using rdsf::ClipResampler;
using rdsf::FrameCandidates;
using rdsf::GroundTruth;

const cv::Rect kPerson(100, 100, 50, 150);
const cv::Rect kElsewhere(400, 100, 50, 150);

// A frame with one person at kPerson; `found`: a candidate on them scoring `person_score`; `false_positive`: a
// candidate elsewhere scoring `other_score`.
void add_frame(std::vector<FrameCandidates>& frames, GroundTruth& truth, const std::string& name, bool found,
               double person_score, bool false_positive, double other_score) {
  FrameCandidates f{name, {}};
  if (found) f.candidates.push_back({kPerson, person_score, {}});
  if (false_positive) f.candidates.push_back({kElsewhere, other_score, {}});
  frames.push_back(f);
  rdsf::TruthBox t;
  t.box = kPerson;
  truth.frames[name].push_back(t);
}

std::string number(int n) {
  char name[16];
  std::snprintf(name, sizeof name, "%06d", n);
  return name;
}

TEST(ClipBootstrap, ClipsAreNumberBlocksOrNameStems) {
  EXPECT_EQ(rdsf::clip_of("000240", 60), "#4");
  EXPECT_EQ(rdsf::clip_of("000299", 60), "#4");
  EXPECT_EQ(rdsf::clip_of("000300", 60), "#5");
  EXPECT_EQ(rdsf::clip_of("12345", 100), "#123");
  EXPECT_EQ(rdsf::clip_of("lab_juggling2", 60), "lab_juggling");
  EXPECT_EQ(rdsf::clip_of("lab_height01", 60), "lab_height");
  EXPECT_EQ(rdsf::clip_of("lab_david_arnaud3", 60), "lab_david_arnaud");
  EXPECT_EQ(rdsf::clip_of("home_2013-10-05_15-46-03-286", 60), "home");
  EXPECT_EQ(rdsf::clip_of("corridor", 60), "corridor");
  EXPECT_THROW(rdsf::clip_of("000001", 0), rdsf::Error);
}

TEST(ClipBootstrap, AllWeightsOneGiveTheExactCurvesTarAtEveryFppf) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> score(-2.0, 2.0);
  std::vector<FrameCandidates> frames;
  GroundTruth truth;
  for (int i = 0; i < 300; ++i) {
    add_frame(frames, truth, number(i), random() % 5 != 0, score(random), random() % 3 == 0, score(random) - 0.5);
  }
  const ClipResampler by_clip(frames, truth, 60);
  ASSERT_EQ(by_clip.clips(), 5);
  const std::vector<rdsf::DetectionFigures> curve = rdsf::exact_detection_curve(frames, truth, false);
  for (double max_fppf : {0.0, 0.01, 0.05, 0.1, 0.2, 0.5, 1.0}) {
    double best = 0;
    for (const rdsf::DetectionFigures& f : curve) {
      if (f.fppf <= max_fppf) best = std::max(best, f.tar);
    }
    EXPECT_DOUBLE_EQ(by_clip.tar_at_fppf(std::vector<int>(5, 1), max_fppf), best) << max_fppf;
  }
  // A clip counted twice weighs twice: clip #0 alone twice is clip #0 alone.
  EXPECT_DOUBLE_EQ(by_clip.tar_at_fppf({2, 0, 0, 0, 0}, 0.1), by_clip.tar_at_fppf({1, 0, 0, 0, 0}, 0.1));
}

TEST(ClipBootstrap, OneRoomWhoseEveryFrameMissesWidensTheIntervalOverClips) {
  // Eight clips of 20 frames: seven find their person in every frame, one (#3) in none. Over the 160
  // person-frames TAR is 0.875 and Wilson's interval is narrow; over clips a draw holds the failing clip
  // 0 to 3 times, so the interval reaches well below.
  std::vector<FrameCandidates> frames;
  GroundTruth truth;
  for (int i = 0; i < 160; ++i) add_frame(frames, truth, number(i), i / 20 != 3, 1.0, false, 0.0);
  const ClipResampler by_clip(frames, truth, 20);
  EXPECT_DOUBLE_EQ(by_clip.tar_at_fppf(std::vector<int>(8, 1), 0.1), 0.875);
  const rdsf::ClipInterval clip = by_clip.interval(0.1);
  ASSERT_TRUE(clip.known());
  EXPECT_EQ(clip.clips, 8);
  const rdsf::RateInterval people = rdsf::wilson_interval(140, 160);
  EXPECT_LT(clip.interval.low, people.low - 0.05) << clip.interval.low << " " << people.low;
  EXPECT_LE(clip.interval.low, 0.75);
  EXPECT_DOUBLE_EQ(clip.interval.high, 1.0);
  // The same seed gives the same interval; another seed may move it, never outside [0, 1].
  const rdsf::ClipInterval again = by_clip.interval(0.1);
  EXPECT_EQ(again.interval.low, clip.interval.low);
  EXPECT_EQ(again.interval.high, clip.interval.high);
  const rdsf::ClipInterval other = by_clip.interval(0.1, 500, 99);
  EXPECT_GE(other.interval.low, 0.0);
  EXPECT_LE(other.interval.high, 1.0);
}

TEST(ClipBootstrap, DrawsOfClipsWithNobodyHaveNoTar) {
  // Four clips of 10 frames, two of them with nobody who counts (their one person 20 % visible): a draw of
  // only those has no TAR and is left out, so the interval does not reach 0 though every person of the two
  // other clips is found.
  std::vector<FrameCandidates> frames;
  GroundTruth truth;
  for (int i = 0; i < 40; ++i) {
    add_frame(frames, truth, number(i), true, 1.0, false, 0.0);
    if ((i / 10) % 2 == 1) truth.frames[number(i)][0].ignored = true;
  }
  const ClipResampler by_clip(frames, truth, 10);
  const rdsf::ClipInterval clip = by_clip.interval(0.1);
  ASSERT_TRUE(clip.known());
  EXPECT_DOUBLE_EQ(clip.interval.low, 1.0);
  EXPECT_DOUBLE_EQ(clip.interval.high, 1.0);
}

TEST(ClipBootstrap, OneClipHasNoInterval) {
  std::vector<FrameCandidates> frames;
  GroundTruth truth;
  for (int i = 1; i <= 12; ++i) add_frame(frames, truth, "home_" + std::to_string(i), i % 2 == 0, 1.0, false, 0.0);
  const ClipResampler by_clip(frames, truth, 60);
  EXPECT_EQ(by_clip.clips(), 1);
  EXPECT_FALSE(by_clip.interval(0.1).known());
}

TEST(ClipBootstrap, EachClipsFiguresAtAThreshold) {
  std::vector<FrameCandidates> frames;
  GroundTruth truth;
  add_frame(frames, truth, "lab_a1", true, 2.0, true, 1.5);   // found; false positive above 1
  add_frame(frames, truth, "lab_a2", true, 0.5, false, 0.0);  // a candidate, below 1
  add_frame(frames, truth, "lab_b1", false, 0.0, true, 0.2);  // no candidate; false positive below 1
  truth.frames["lab_b1"].push_back({kElsewhere, 2, 2, 0.2, true});  // an ignored person under the false positive
  const ClipResampler by_clip(frames, truth, 60);
  const std::vector<rdsf::ClipFigures> at1 = by_clip.figures(1.0);
  ASSERT_EQ(at1.size(), 2u);
  EXPECT_EQ(at1[0].clip, "lab_a");
  EXPECT_EQ(at1[0].frames, 2);
  EXPECT_EQ(at1[0].people, 2);
  EXPECT_EQ(at1[0].with_candidate, 2);
  EXPECT_EQ(at1[0].detected, 1);
  EXPECT_EQ(at1[0].false_positives, 1);
  EXPECT_EQ(at1[1].clip, "lab_b");
  EXPECT_EQ(at1[1].people, 1);
  EXPECT_EQ(at1[1].with_candidate, 0);
  EXPECT_EQ(at1[1].detected, 0);
  EXPECT_EQ(at1[1].false_positives, 0);  // the candidate covers only an ignored person: neutral
  const std::vector<rdsf::ClipFigures> at0 = by_clip.figures(0.0);
  EXPECT_EQ(at0[0].detected, 2);
  EXPECT_EQ(at0[1].false_positives, 0);
}

}  // namespace

namespace {

// Ten clips of 10 frames with one person each; `found(clip)` says whether the model finds the person in the
// frames of that clip (a score of 1 on them), and every frame has a false positive scoring -1.
ClipResampler model_finding(std::vector<FrameCandidates>& frames, GroundTruth& truth, bool (*found)(int)) {
  frames.clear();
  truth.frames.clear();
  for (int i = 0; i < 100; ++i) add_frame(frames, truth, number(i), found(i / 10), 1.0, true, -1.0);
  return ClipResampler(frames, truth, 10);
}

TEST(ClipBootstrap, PairedDifferenceOfTwoModelsOnTheSameClips) {
  std::vector<FrameCandidates> frames;
  GroundTruth truth;
  // a finds the people of clips 0-5; b those of clips 0-6: b is 0.1 better, in one clip of ten.
  const ClipResampler a = model_finding(frames, truth, [](int clip) { return clip <= 5; });
  const ClipResampler b = model_finding(frames, truth, [](int clip) { return clip <= 6; });
  const rdsf::ClipDifference d = rdsf::paired_difference(a, b, 0.1);
  EXPECT_NEAR(d.difference, 0.1, 1e-12);
  ASSERT_TRUE(d.interval.known());
  EXPECT_EQ(d.interval.clips, 10);
  // Paired, the rooms both models find hard cancel: the difference never goes below 0 and its interval is
  // at most half as wide as either figure's own (a: 0.3-0.9).
  EXPECT_GE(d.interval.interval.low, 0.0);
  EXPECT_LE(d.interval.interval.high, 0.3 + 1e-9);  // a draw holds the one differing clip up to 3 times
  const rdsf::RateInterval ia = a.interval(0.1).interval, ib = b.interval(0.1).interval;
  EXPECT_LE(d.interval.interval.high - d.interval.interval.low, (ia.high - ia.low) / 2 + 1e-9)
      << ia.low << "-" << ia.high;
  EXPECT_GT(ib.high - ib.low, 0.3);
  // A model against itself: 0, exactly.
  const rdsf::ClipDifference same = rdsf::paired_difference(a, a, 0.5);
  EXPECT_EQ(same.difference, 0.0);
  EXPECT_EQ(same.interval.interval.low, 0.0);
  EXPECT_EQ(same.interval.interval.high, 0.0);
  // Evaluations of other frames are refused.
  std::vector<FrameCandidates> other_frames;
  GroundTruth other_truth;
  for (int i = 0; i < 30; ++i) add_frame(other_frames, other_truth, number(i), true, 1.0, false, 0.0);
  const ClipResampler other(other_frames, other_truth, 10);
  EXPECT_THROW(rdsf::paired_difference(a, other, 0.1), rdsf::Error);
}

}  // namespace
