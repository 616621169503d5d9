// Candidates for every person on hand-built depth maps: boxes that fit (side-on people, arms), joined
// pieces, splitting people side by side, overlapping people between their heads (not at a raised hand)
// and a person against a cupboard, people cut by the border, and the thesis preset.
#include <gtest/gtest.h>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "support/depth_scenes.hpp"

using namespace rdsf;

namespace {

// The defaults with the fitted box at the layer's extent alone (fit.min_width_ratio 0): most tests here
// check that extent; FittedBoxIsAtLeastTheMinimumWidthRatioOfItsHeight checks the widening on top of it.
AnalyserParams extent() {
  AnalyserParams p;
  p.candidates.fit.min_width_ratio = 0;
  return p;
}

std::vector<Candidate> at_depth(const DepthFrame& frame, double depth_mm, AnalyserParams params = extent(),
                                double tolerance_mm = 30) {
  std::vector<Candidate> found;
  for (const Candidate& c : FrameAnalyser(params).analyse(frame, false).candidates) {
    if (std::abs(c.layer_depth_mm - depth_mm) < tolerance_mm) found.push_back(c);
  }
  return found;
}

double best_iou(const std::vector<Candidate>& candidates, const cv::Rect& truth, BoxKind kind) {
  double best = 0;
  for (const Candidate& c : candidates) best = std::max(best, iou(reported_box(c, kind), truth));
  return best;
}

// A person seen from the front at 2 m: head 40 px wide on rows 100-149, body `body_px` wide below to 459.
void paint_person(DepthFrame& frame, int left, int body_px, int depth_mm = 2000) {
  test::paint(frame, {left + body_px / 2 - 20, 100, 40, 50}, depth_mm);
  test::paint(frame, {left, 150, body_px, 310}, depth_mm);
}

// The wide-object cuts alone (heads off).
AnalyserParams splitting() {
  AnalyserParams p = extent();
  p.candidates.split_head.drop_cm = 0;
  p.candidates.split.valley_cm = 15;
  p.candidates.split.step_cm = 30;
  p.candidates.split.depth_jump_mm = 250;
  return p;
}

AnalyserParams splitting_off() {
  AnalyserParams p = extent();
  p.candidates.split_head.drop_cm = 0;
  return p;
}

}  // namespace

TEST(CandidateShapes, SideOnPersonGetsAFittedBoxWithinTenPercent) {
  DepthFrame frame = test::wall_frame(4000);
  const cv::Rect person(300, 60, 60, 400);  // 23 cm x 152 cm at 2 m: side-on
  test::paint(frame, person, 2000);
  const auto found = at_depth(frame, 2000);  // the layer's extent alone: no minimum width for the box
  ASSERT_EQ(found.size(), 1u);
  const cv::Rect& fitted = found[0].fitted_box;
  EXPECT_LE(std::abs(fitted.x - person.x), person.width / 10);
  EXPECT_LE(std::abs(fitted.width - person.width), person.width / 10);
  EXPECT_LE(std::abs(fitted.y - person.y), person.height / 10);
  EXPECT_LE(std::abs(fitted.height - person.height), person.height / 10);
  EXPECT_LT(iou(found[0].strict_box, person), 0.5);  // height/2 wide: the thesis's box cannot match
  EXPECT_EQ(found[0].strict_box, cv::Rect(230, 60, 200, 400));  // the crop's box is unchanged
  // With the defaults the extent is the same; the reported box is widened to 0.3 of the height.
  const auto by_default = at_depth(frame, 2000, AnalyserParams());
  ASSERT_EQ(by_default.size(), 1u);
  EXPECT_EQ(by_default[0].extent_box, fitted);
  EXPECT_EQ(by_default[0].fitted_box.width, 120);
}

TEST(CandidateShapes, FittedBoxIsAtLeastTheMinimumWidthRatioOfItsHeight) {
  // The same slab of 0.15 of its height, and one at the left border: by default each box is widened about
  // its centre to 0.3 of its height (clipped to the image); crops, strict boxes and windows do not change.
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {300, 60, 60, 400}, 2000);
  test::paint(frame, {0, 60, 40, 400}, 2000);  // cut by the left border
  const auto widened = at_depth(frame, 2000, AnalyserParams()), narrow = at_depth(frame, 2000);
  ASSERT_EQ(widened.size(), 2u);
  ASSERT_EQ(narrow.size(), 2u);
  EXPECT_EQ(narrow[0].fitted_box, cv::Rect(0, 60, 40, 400));
  EXPECT_EQ(widened[0].fitted_box, cv::Rect(0, 60, 80, 400));  // centre 20, 120 wide, clipped at 0
  EXPECT_EQ(narrow[1].fitted_box, cv::Rect(300, 60, 60, 400));
  EXPECT_EQ(widened[1].fitted_box, cv::Rect(270, 60, 120, 400));  // centre 330, 0.3 x 400 = 120 wide
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(widened[i].extent_box, narrow[i].fitted_box);  // labelling by overlap uses the extent
    EXPECT_EQ(labelling_box(widened[i], BoxKind::fitted), narrow[i].fitted_box);
    EXPECT_EQ(widened[i].strict_box, narrow[i].strict_box);
    EXPECT_EQ(widened[i].window, narrow[i].window);
    EXPECT_EQ(cv::norm(widened[i].depth_crop, narrow[i].depth_crop, cv::NORM_INF), 0);
  }
  // A box already wider than the ratio keeps its extent.
  AnalyserParams wide;  // the defaults but a ratio of 0.1
  wide.candidates.fit.min_width_ratio = 0.1;
  EXPECT_EQ(at_depth(frame, 2000, wide)[1].fitted_box, cv::Rect(300, 60, 60, 400));
}

TEST(CandidateShapes, FittedBoxReachesOverArmsHeldOut) {
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {300, 100, 60, 360}, 2000);  // body
  test::paint(frame, {230, 160, 70, 20}, 2000);   // an arm held out to the left (27 cm)
  const auto found = at_depth(frame, 2000);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].fitted_box, cv::Rect(230, 100, 130, 360));
  AnalyserParams no_reach = extent();
  no_reach.candidates.fit.reach_cm = 0;
  EXPECT_EQ(at_depth(frame, 2000, no_reach)[0].fitted_box, cv::Rect(300, 100, 60, 360));
}

TEST(CandidateShapes, FittedBoxReachesAnArmBehindSomethingNearer) {
  // A person at 3 m holds an arm out to the right (51 cm); a post at 1.5 m stands before the arm near the
  // body, 20 columns wide (11 cm at 3 m): more than column_gap, less than fit_occlusion_gap (15 cm).
  DepthFrame frame = test::wall_frame(4500);
  test::paint(frame, {300, 100, 60, 360}, 3000);  // body
  test::paint(frame, {360, 160, 90, 20}, 3000);   // the arm
  test::paint(frame, {370, 40, 20, 440}, 1500);   // the post, in front of the arm's columns 370-389
  AnalyserParams on = extent();
  on.candidates.fit.occlusion_gap_cm = 15;
  const auto found = at_depth(frame, 3000, on);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].fitted_box, cv::Rect(300, 100, 150, 360));  // to the hand
  EXPECT_EQ(at_depth(frame, 3000)[0].fitted_box, cv::Rect(300, 100, 70, 360));  // off (the default): stops at the post
  on.candidates.fit.occlusion_gap_cm = 5;  // 8 columns at 3 m, and column_gap's 6: the post's 20 are too many
  EXPECT_EQ(at_depth(frame, 3000, on)[0].fitted_box, cv::Rect(300, 100, 70, 360));
  const auto thesis = at_depth(frame, 3000, thesis_params());
  ASSERT_EQ(thesis.size(), 1u);
  EXPECT_EQ(thesis[0].fitted_box, cv::Rect(300, 100, 60, 360));  // no reach at all
}

TEST(CandidateShapes, FittedBoxDoesNotJumpASmallNearerThingToAnotherObject) {
  // Beside the person at 3 m, 20 columns of nothing of the layer, then a box at the same depth (a chair's
  // back, 30 columns): with a post before the gap the fitted box takes the box; with only a small nearer
  // thing low in the gap (3 of the band's rows, fewer than half the pixels of the column last taken) it
  // does not.
  const auto scene = [](int post_top) {
    DepthFrame frame = test::wall_frame(4500);
    test::paint(frame, {300, 100, 60, 360}, 3000);  // the person
    test::paint(frame, {380, 200, 30, 120}, 3000);  // the box, 69 cm tall: below threshold_height (90)
    test::paint(frame, {360, post_top, 20, 480 - post_top}, 1500);
    return frame;
  };
  AnalyserParams on = extent();
  on.candidates.fit.occlusion_gap_cm = 15;
  const auto big = at_depth(scene(40), 3000, on);
  ASSERT_EQ(big.size(), 1u);
  EXPECT_EQ(big[0].fitted_box, cv::Rect(300, 100, 110, 360));
  const auto small = at_depth(scene(364), 3000, on);
  ASSERT_EQ(small.size(), 1u);
  EXPECT_EQ(small[0].fitted_box, cv::Rect(300, 100, 60, 360));
}

TEST(CandidateShapes, LegsThatPassAloneAreJoinedIntoOnePerson) {
  // Torso rows 100-299 (76 cm: fails 90 cm), legs below to 459 pass: the thesis finds two leg objects.
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {280, 100, 100, 200}, 2000);
  test::paint(frame, {280, 300, 30, 160}, 2000);
  test::paint(frame, {350, 300, 30, 160}, 2000);
  const cv::Rect person(280, 100, 100, 360);
  EXPECT_EQ(at_depth(frame, 2000, thesis_params()).size(), 2u);
  const auto found = at_depth(frame, 2000);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].fitted_box, person);
  EXPECT_GE(found[0].highest_column, 280);  // the middle of the columns reaching the top (the thesis's rule)
  EXPECT_LT(found[0].highest_column, 380);
}

TEST(CandidateShapes, TwoPeopleSideBySideAtOneDepthGiveTwoCandidates) {
  DepthFrame frame = test::wall_frame(4000);
  paint_person(frame, 150, 144);  // shoulders 55 cm wide, touching
  paint_person(frame, 294, 144);
  const cv::Rect left(150, 100, 144, 360), right(294, 100, 144, 360);
  const auto whole = at_depth(frame, 2000, splitting_off());  // without splitting: one object
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_LE(best_iou(whole, left, BoxKind::fitted), 0.5);
  const auto split = at_depth(frame, 2000, splitting());
  ASSERT_EQ(split.size(), 2u);
  EXPECT_TRUE(split[0].part && split[1].part);
  EXPECT_GE(best_iou(split, left, BoxKind::fitted), 0.8);
  EXPECT_GE(best_iou(split, right, BoxKind::fitted), 0.8);
  AnalyserParams both = splitting();
  both.candidates.split.keep_whole = true;
  EXPECT_EQ(at_depth(frame, 2000, both).size(), 3u);
}

TEST(CandidateShapes, PeopleOverlappingAtOneDepthAreCutBetweenTheirHeads) {
  // Bodies 42 cm wide overlapping by 8 cm: 72 cm together, narrower than max_person_width (the wide-object
  // cuts never try it); heads 15 cm wide, 19 cm above the shoulders.
  DepthFrame frame = test::wall_frame(4000);
  paint_person(frame, 150, 110);
  paint_person(frame, 230, 110);
  const cv::Rect left(150, 100, 110, 360), right(230, 100, 110, 360), both(150, 100, 190, 360);
  const auto whole = at_depth(frame, 2000, splitting_off());
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_LT(best_iou(whole, left, BoxKind::fitted), 0.6);
  const auto found = at_depth(frame, 2000);  // the default: both pieces
  ASSERT_EQ(found.size(), 2u);
  EXPECT_TRUE(found[0].part && found[1].part);
  EXPECT_GE(best_iou(found, left, BoxKind::fitted), 0.8);
  EXPECT_GE(best_iou(found, right, BoxKind::fitted), 0.8);
  AnalyserParams keep = extent();
  keep.candidates.split_head.keep_whole = true;
  const auto with_whole = at_depth(frame, 2000, keep);
  ASSERT_EQ(with_whole.size(), 3u);
  EXPECT_GE(best_iou(with_whole, both, BoxKind::fitted), 0.95);
  AnalyserParams shallow = extent();  // shoulders less than 25 cm below the heads: no heads
  shallow.candidates.split_head.drop_cm = 25;
  EXPECT_EQ(at_depth(frame, 2000, shallow).size(), 1u);
  AnalyserParams far = extent();  // heads only in layers nearer than split_head_layers_below
  far.candidates.split_head.layers_below_mm = 2000;
  EXPECT_EQ(at_depth(frame, 2000, far).size(), 1u);
}

TEST(CandidateShapes, PiecesCutBetweenHeadsFitAcrossTheCutOverAnArmHeldOut) {
  // Two people 37 cm wide at 2 m, 60 px apart, the right one holding an arm out (23 cm) to the left one's
  // side: joined into one object (the fitted extents touch, 97 cm together), cut between the heads in
  // the middle of the arm (the lowest point between them).
  DepthFrame frame = test::wall_frame(4000);
  paint_person(frame, 150, 96);
  paint_person(frame, 306, 96);
  test::paint(frame, {246, 200, 60, 20}, 2000);
  const auto found = at_depth(frame, 2000);
  ASSERT_EQ(found.size(), 2u);
  ASSERT_TRUE(found[0].part && found[1].part);
  // Each piece reaches over the whole arm up to the other's body: the arm is either's.
  const cv::Rect right_with_arm(246, 100, 156, 360);
  EXPECT_EQ(found[0].fitted_box, cv::Rect(150, 100, 156, 360));
  EXPECT_EQ(found[1].fitted_box, right_with_arm);
  AnalyserParams at_cut = extent();  // each piece within its side of the cut
  at_cut.candidates.fit.across_head_cut = false;
  const auto cut = at_depth(frame, 2000, at_cut);
  ASSERT_EQ(cut.size(), 2u);
  EXPECT_EQ(cut[0].fitted_box.br().x, cut[1].fitted_box.x);  // they meet at the cut, inside the arm
  EXPECT_GT(cut[1].fitted_box.x, 246 + 10);
  EXPECT_LT(cut[1].fitted_box.x, 306 - 10);
  EXPECT_LT(iou(cut[1].fitted_box, right_with_arm), iou(found[1].fitted_box, right_with_arm));
  // Crops and strict boxes do not depend on it.
  EXPECT_EQ(cut[1].strict_box, found[1].strict_box);
  EXPECT_EQ(cv::norm(cut[1].depth_crop, found[1].depth_crop, cv::NORM_INF), 0);
}

TEST(CandidateShapes, ARaisedHandIsNoHead) {
  DepthFrame frame = test::wall_frame(4000);
  paint_person(frame, 280, 200);                  // head 15 cm wide on columns 360-399
  test::paint(frame, {450, 90, 20, 120}, 2000);  // a hand raised above the head and the shoulder: 8 cm wide
  const auto found = at_depth(frame, 2000);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].fitted_box, cv::Rect(280, 90, 200, 370));
  AnalyserParams any_width = extent();  // without the narrowest head top, the hand is a second head
  any_width.candidates.split_head.min_width_cm = 0;
  EXPECT_EQ(at_depth(frame, 2000, any_width).size(), 2u);
}

TEST(CandidateShapes, AHeadNeedsShouldersInsideTheObject) {
  // A lamp post (15 cm) touching a person, as tall as the head: a top with a drop on one side only, where
  // the object ends (not at the image's border): no second head.
  DepthFrame frame = test::wall_frame(4000);
  paint_person(frame, 150, 110);
  test::paint(frame, {260, 100, 40, 360}, 2000);
  ASSERT_EQ(at_depth(frame, 2000).size(), 1u);
  // The same shapes cut by the image's right border: the lamp could be a head whose shoulder is outside.
  DepthFrame border = test::wall_frame(4000);
  paint_person(border, 490, 110);
  test::paint(border, {600, 100, 40, 360}, 2000);
  EXPECT_EQ(at_depth(border, 2000).size(), 2u);
}

TEST(CandidateShapes, PersonAgainstACupboardAtTheSameDepthIsSplitOff) {
  DepthFrame frame = test::wall_frame(4000);
  const cv::Rect person(150, 100, 120, 360);  // 46 cm x 137 cm
  test::paint(frame, person, 2000);
  test::paint(frame, {270, 200, 300, 260}, 2000);  // a cupboard touching it: 114 cm wide, 99 cm high
  const auto whole = at_depth(frame, 2000);
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_LT(best_iou(whole, person, BoxKind::fitted), 0.5);
  const auto split = at_depth(frame, 2000, splitting());
  EXPECT_GE(best_iou(split, person, BoxKind::fitted), 0.8);
}

TEST(CandidateShapes, PersonBeforeACupboardInTheSameLayerIsSplitOffByDepth) {
  DepthFrame frame = test::wall_frame(5000);
  const cv::Rect person(150, 60, 120, 400);
  test::paint(frame, {270, 60, 300, 400}, 2400);  // a tall cupboard 40 cm behind, in the person's layer
  test::paint(frame, person, 2000);
  const auto whole = at_depth(frame, 2200, {}, 250);
  ASSERT_EQ(whole.size(), 1u);  // one layer, one object
  EXPECT_LT(best_iou(whole, person, BoxKind::fitted), 0.5);
  const auto split = at_depth(frame, 2200, splitting(), 250);
  EXPECT_GE(best_iou(split, person, BoxKind::fitted), 0.8);
}

TEST(CandidateShapes, PeopleCutByTheBorderKeepABoxInsideTheImage) {
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {0, 100, 40, 380}, 2000);    // cut by the left and bottom borders
  test::paint(frame, {610, 100, 30, 380}, 2000);  // cut by the right and bottom borders
  const cv::Rect image(0, 0, 640, 480);
  const auto found = at_depth(frame, 2000);
  ASSERT_EQ(found.size(), 2u);
  for (const Candidate& c : found) {
    EXPECT_EQ(c.fitted_box & image, c.fitted_box);
    EXPECT_EQ(c.strict_box & image, c.strict_box);
    EXPECT_EQ(c.fitted_box.y + c.fitted_box.height, 480);
    // The crop keeps the person's proportions: the window is the strict box's, leaving the image.
    EXPECT_EQ(c.window_unclipped.width, std::lround(std::lround(380 / 2.0) * 1.25));
  }
  EXPECT_EQ(found[0].fitted_box, cv::Rect(0, 100, 40, 380));
  EXPECT_EQ(found[1].fitted_box, cv::Rect(610, 100, 30, 380));
}

TEST(CandidateShapes, NarrowPiecesAreNotCandidatesUnlessCutByTheBorder) {
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {300, 60, 30, 400}, 2000);  // 11 cm wide: a post, not a person
  EXPECT_TRUE(at_depth(frame, 2000).empty());
  AnalyserParams off = extent();
  off.candidates.min_fitted_width_cm = 0;
  EXPECT_EQ(at_depth(frame, 2000, off).size(), 1u);
}

TEST(CandidateShapes, ThesisPresetTurnsEveryDepartureOff) {
  const AnalyserParams t = thesis_params();
  EXPECT_FALSE(t.segmentation.left_border_jump);
  EXPECT_EQ(t.candidates.occlusion_gap_cm, 0);
  EXPECT_EQ(t.candidates.hole_gap_cm, 0);
  EXPECT_EQ(t.candidates.floor_tolerance_mm, 0);
  EXPECT_FALSE(t.candidates.height_at_column_depth);
  EXPECT_EQ(t.candidates.fit.reach_cm, 0);
  EXPECT_EQ(t.candidates.fit.occlusion_gap_cm, 0);
  EXPECT_EQ(t.candidates.fit.min_width_ratio, 0);
  EXPECT_FALSE(t.candidates.join.pieces);
  EXPECT_EQ(t.candidates.max_object_width_cm, 0);
  EXPECT_EQ(t.candidates.min_fitted_width_cm, 0);
  EXPECT_EQ(t.candidates.narrow.fitted_width_cm, 0);
  EXPECT_EQ(t.candidates.split.depth_jump_mm + t.candidates.split.valley_cm + t.candidates.split.step_cm, 0);
  EXPECT_EQ(t.candidates.split_head.drop_cm, 0);
  EXPECT_FALSE(t.candidates.fit.across_head_cut);
  EXPECT_EQ(t.reported_box, BoxKind::strict);
  EXPECT_EQ(AnalyserParams().reported_box, BoxKind::fitted);
}
