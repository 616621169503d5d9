// The shape of a person's miss (include/rdsf/evaluation/candidate_misses.hpp): each rule at its bounds,
// the order the rules are tested in, and the counts' summary.
#include <gtest/gtest.h>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/evaluation/candidate_misses.hpp"

namespace rdsf {
namespace {

const cv::Rect kPerson(200, 100, 100, 300);

MissShape shape_of(const cv::Rect& best) { return miss_shape(kPerson, best, iou(best, kPerson)); }

TEST(CandidateMisses, EachShapeAtItsBounds) {
  // The rules read the sizes and the IoU given (a box can be 1.41 wide and overlap at 0.71, a match).
  const auto at = [](const cv::Rect& best) { return miss_shape(kPerson, best, 0.3); };
  EXPECT_EQ(at(cv::Rect(200, 100, 141, 300)), MissShape::wide);  // 1.41
  EXPECT_EQ(at(cv::Rect(200, 100, 140, 300)), MissShape::shifted);  // 1.40: not wide
  EXPECT_EQ(at(cv::Rect(200, 100, 69, 300)), MissShape::narrow);  // 0.69
  EXPECT_EQ(at(cv::Rect(200, 100, 70, 300)), MissShape::shifted);  // 0.70: not narrow
  EXPECT_EQ(at(cv::Rect(200, 0, 100, 391)), MissShape::tall);     // 1.303
  EXPECT_EQ(at(cv::Rect(200, 0, 100, 390)), MissShape::shifted);  // 1.30: not tall
  EXPECT_EQ(at(cv::Rect(200, 100, 100, 224)), MissShape::short_box);  // 0.747
  EXPECT_EQ(at(cv::Rect(200, 100, 100, 225)), MissShape::shifted);    // 0.75: not short
  EXPECT_EQ(miss_shape(kPerson, kPerson, 0.0999), MissShape::none);   // below 0.1, whatever the size
  EXPECT_EQ(miss_shape(kPerson, kPerson, 0.1), MissShape::shifted);
  EXPECT_EQ(miss_shape(kPerson, cv::Rect(), 0.0), MissShape::none);   // no candidate at all
}

TEST(CandidateMisses, BoxesAsTheyOverlap) {
  EXPECT_EQ(shape_of(cv::Rect(0, 0, 10, 10)), MissShape::none);         // far away: IoU 0
  EXPECT_EQ(shape_of(cv::Rect(150, 100, 201, 300)), MissShape::wide);   // joined: 2x wide, IoU 0.4975
  EXPECT_EQ(shape_of(cv::Rect(200, 100, 45, 300)), MissShape::narrow);  // one leg: IoU 0.45
  EXPECT_EQ(shape_of(cv::Rect(260, 100, 100, 300)), MissShape::shifted);  // the right size, 60 px off: 0.25
}

TEST(CandidateMisses, WidthIsTestedBeforeHeight) {
  EXPECT_EQ(miss_shape(kPerson, cv::Rect(150, 0, 160, 420), 0.3), MissShape::wide);   // wide and tall
  EXPECT_EQ(miss_shape(kPerson, cv::Rect(220, 150, 60, 200), 0.3), MissShape::narrow);  // narrow and short
}

TEST(CandidateMisses, AMatchIsNoMiss) {
  EXPECT_THROW(miss_shape(kPerson, kPerson, 1.0), Error);
  EXPECT_THROW(miss_shape(kPerson, kPerson, 0.5), Error);
}

TEST(CandidateMisses, SummaryListsTheShapesThatOccurMostFirst) {
  MissShapes shapes;
  EXPECT_EQ(shapes.summary(), "");
  EXPECT_EQ(shapes.total(), 0);
  for (int i = 0; i < 4; ++i) shapes.add(MissShape::wide);
  for (int i = 0; i < 11; ++i) shapes.add(MissShape::narrow);
  shapes.add(MissShape::none);
  shapes.add(MissShape::shifted);
  EXPECT_EQ(shapes.summary(), "11 narrow, 4 wide, 1 none, 1 shifted");  // ties in MissShape's order
  EXPECT_EQ(shapes.total(), 17);
  EXPECT_STREQ(miss_shape_name(MissShape::short_box), "short");
}

}  // namespace
}  // namespace rdsf
