// Narrow people (CandidateParams::narrow.fitted_width_cm, step 4 of include/rdsf/candidates/layer_objects.hpp)
// on hand-built depth maps: a person whose only passing columns (the legs, together) are narrower than
// min_width_cm stays a candidate; narrow things that are not person-like (reaching the top of the image,
// holes above them, too short, too far) do not.
#include <gtest/gtest.h>

#include <cmath>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "support/depth_scenes.hpp"

using namespace rdsf;

namespace {

// The rule is off by default (narrow.fitted_width_cm = 0, see candidate_params.hpp); these tests turn it on.
AnalyserParams narrow_on() {
  AnalyserParams p;
  p.candidates.narrow.fitted_width_cm = 20;
  return p;
}

std::vector<Candidate> at_depth(const DepthFrame& frame, double depth_mm, AnalyserParams params = narrow_on()) {
  std::vector<Candidate> found;
  for (const Candidate& c : FrameAnalyser(params).analyse(frame, false).candidates) {
    if (std::abs(c.layer_depth_mm - depth_mm) < 30) found.push_back(c);
  }
  return found;
}

// A person at `depth_mm` from `top` down (sizes in cm, 1.75 px per cm at 3 m): a 17 x 17 cm head, a 40 cm
// wide torso 63 cm high, legs together 8 cm wide and 69 cm high. The columns beside the legs hold 80 cm and
// fail threshold_height (90 cm far); the leg columns (149 cm) pass, 8 cm of them. Returns the person's box.
cv::Rect paint_narrow_person(DepthFrame& frame, int top, int depth_mm = 3000) {
  const auto px = [depth_mm](double cm) { return static_cast<int>(std::lround(cm * 525.0 * 10.0 / depth_mm)); };
  const int x = 300, head = px(17), torso = px(63), legs = px(69);
  test::paint(frame, {x + (px(40) - head) / 2, top, head, head}, depth_mm);
  test::paint(frame, {x, top + head, px(40), torso}, depth_mm);
  test::paint(frame, {x + (px(40) - px(8)) / 2, top + head + torso, px(8), legs}, depth_mm);
  return {x, top, px(40), head + torso + legs};
}

}  // namespace

TEST(NarrowPeople, PersonWhosePassingColumnsAreNarrowerThanMinWidthIsACandidate) {
  DepthFrame frame = test::wall_frame(5000);
  const cv::Rect person = paint_narrow_person(frame, 160);
  const auto found = at_depth(frame, 3000);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_GE(iou(found[0].extent_box, person), 0.9);  // its extent (the fitted box widens it to 0.3 of its height)
  EXPECT_LT(found[0].width_cm, 10.0);  // its passing columns: narrower than min_width_cm
  // Off (the default, and in the thesis preset): the thesis's min_width_cm drops it.
  AnalyserParams off = narrow_on();
  off.candidates.narrow.fitted_width_cm = 0;
  EXPECT_TRUE(at_depth(frame, 3000, off).empty());
  EXPECT_TRUE(at_depth(frame, 3000, AnalyserParams{}).empty());
  EXPECT_TRUE(at_depth(frame, 3000, thesis_params()).empty());
  EXPECT_EQ(thesis_params().candidates.narrow.fitted_width_cm, 0);
}

TEST(NarrowPeople, NarrowObjectReachingTheTopOfTheImageIsNot) {
  // A door frame or a post with a shelf: nothing but the image border above its top.
  DepthFrame frame = test::wall_frame(5000);
  paint_narrow_person(frame, 0);
  EXPECT_TRUE(at_depth(frame, 3000).empty());
  // Missing readings above it, not a background: neither.
  DepthFrame holes = test::wall_frame(5000);
  paint_narrow_person(holes, 160);
  test::paint(holes, {290, 130, 90, 30}, 0);
  EXPECT_TRUE(at_depth(holes, 3000).empty());
  // Something nearer above the head (a hanging bag) is a background too.
  DepthFrame bag = test::wall_frame(5000);
  paint_narrow_person(bag, 160);
  test::paint(bag, {290, 60, 90, 100}, 1500);
  EXPECT_EQ(at_depth(bag, 3000).size(), 1u);
}

TEST(NarrowPeople, NarrowObjectTooShortOrTooFarIsNot) {
  // 80 cm: a chair's back and leg at 3 m, its leg columns passing near threshold_height (50 cm, relaxed).
  DepthFrame chair = test::wall_frame(5000);
  test::paint(chair, {300, 300, 70, 40}, 3000);   // seat and back, 23 cm
  test::paint(chair, {328, 340, 14, 100}, 3000);  // the leg, 57 cm
  AnalyserParams relaxed = narrow_on();
  relaxed.candidates.mode = HeightMode::relaxed;
  EXPECT_TRUE(at_depth(chair, 3000, relaxed).empty());
  relaxed.candidates.narrow.min_height_cm = 0;
  EXPECT_EQ(at_depth(chair, 3000, relaxed).size(), 1u);
  // The person beyond narrow.layers_below_mm (5 m) is not kept.
  DepthFrame far = test::wall_frame(7000);
  paint_narrow_person(far, 160, 5500);
  AnalyserParams strict = narrow_on();
  EXPECT_TRUE(at_depth(far, 5500, strict).empty());
  strict.candidates.narrow.layers_below_mm = 6000;
  EXPECT_EQ(at_depth(far, 5500, strict).size(), 1u);
}

TEST(NarrowPeople, NarrowPassingColumnsMustBeWideEnoughAndTheBodyAPersonsWidth) {
  DepthFrame frame = test::wall_frame(5000);
  paint_narrow_person(frame, 160);
  AnalyserParams wider_body = narrow_on();
  wider_body.candidates.narrow.fitted_width_cm = 45;  // the body is 40 cm
  EXPECT_TRUE(at_depth(frame, 3000, wider_body).empty());
  AnalyserParams wider_legs = narrow_on();
  wider_legs.candidates.narrow.passing_width_cm = 9;  // the legs are 8 cm
  EXPECT_TRUE(at_depth(frame, 3000, wider_legs).empty());
}

TEST(NarrowPeople, JoinNarrowPassingJoinsLegsButNotTheSlatsOfAChairBack) {
  // At 1.4 m (3.75 px per cm, near threshold_height 50 cm): three slats 3 px (0.8 cm) wide and 250 rows
  // (67 cm) high under a 20-row rail: each passes, too narrow alone; their fitted extents touch over the rail.
  DepthFrame chair = test::wall_frame(4000);
  test::paint(chair, {298, 200, 70, 20}, 1400);
  for (int x : {300, 330, 362}) test::paint(chair, {x, 220, 3, 230}, 1400);
  AnalyserParams any;
  any.candidates.join.narrow_passing = false;
  EXPECT_EQ(at_depth(chair, 1400, any).size(), 1u);  // joined: 17 cm over its passing columns
  const AnalyserParams passing;  // join.narrow_passing: 2.4 cm of passing columns, below 5 cm
  EXPECT_TRUE(at_depth(chair, 1400, passing).empty());
  // Two legs of 20 px (5.3 cm) under a torso 48 cm high (failing 50 cm alone) still join into one person.
  DepthFrame legs = test::wall_frame(4000);
  test::paint(legs, {280, 180, 100, 180}, 1400);
  test::paint(legs, {280, 360, 20, 110}, 1400);
  test::paint(legs, {360, 360, 20, 110}, 1400);
  const auto found = at_depth(legs, 1400, passing);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_GE(iou(found[0].fitted_box, cv::Rect(280, 180, 100, 290)), 0.9);
}
