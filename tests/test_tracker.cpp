#include <gtest/gtest.h>

#include "rdsf/tracking/colour_histogram.hpp"
#include "rdsf/tracking/tracker.hpp"

using namespace rdsf;

namespace {

ColourHistogram uniform_colour(cv::Vec3b colour) {
  return ColourHistogram::of(cv::Mat3b(128, 64, colour), cv::Mat1w(128, 64, std::uint16_t{2000}));
}

TrackInput at(int x, double depth_mm, cv::Vec3b colour = {0, 0, 255}) {
  return {cv::Rect(x, 100, 100, 200), depth_mm, uniform_colour(colour)};
}

}  // namespace

TEST(ColourHistogram, OnlyMaskedPixelsCount) {
  cv::Mat3b colour(128, 64, cv::Vec3b(0, 0, 255));
  colour(cv::Rect(0, 0, 64, 64)).setTo(cv::Scalar(255, 0, 0));
  cv::Mat1w depth(128, 64, std::uint16_t{0});
  depth(cv::Rect(0, 64, 64, 64)).setTo(2000);  // only the red half is in the layer
  const ColourHistogram h = ColourHistogram::of(colour, depth);
  ASSERT_EQ(h.values.size(), 512u);
  EXPECT_FLOAT_EQ(h.values[7], 1.0f);  // (B 0, G 0, R 7)
  EXPECT_DOUBLE_EQ(bhattacharyya_coefficient(h, h), 1.0);
  EXPECT_DOUBLE_EQ(bhattacharyya_distance(h, uniform_colour({255, 0, 0})), 1.0);
  EXPECT_TRUE(ColourHistogram::of(cv::Mat3b(), depth).empty());
}

TEST(Tracker, LkhIsHistogramDistancePlusScaledDistance) {
  const ColourHistogram red = uniform_colour({0, 0, 255});
  EXPECT_NEAR(match_lkh(red, red, 2.0), 0.0, 1e-12);     // same colour, 2 cm: 0
  EXPECT_NEAR(match_lkh(red, red, 100.0), 1.0, 1e-12);   // 100 cm: 1
  EXPECT_NEAR(match_lkh(red, uniform_colour({255, 0, 0}), 2.0), 1.0, 1e-12);
  EXPECT_NEAR(match_lkh(ColourHistogram{}, red, 51.0), 0.5, 1e-12);  // no colour: distance term alone
}

TEST(Tracker, CentroidsInCentimetres) {
  const CameraModel camera;
  const cv::Point3d c = centroid_cm(cv::Rect(269, 189, 101, 101), 2000, camera);  // centre (319.5, 239.5)
  EXPECT_NEAR(c.x, 0.0, 1e-9);
  EXPECT_NEAR(c.y, 0.0, 1e-9);
  EXPECT_NEAR(c.z, 200.0, 1e-9);
  EXPECT_NEAR(centroid_cm(cv::Rect(794, 189, 101, 101), 2000, camera).x, 200.0, 1e-9);  // 525 px at 2 m = 2 m
}

TEST(Tracker, FollowsTwoPeopleAndCountsDistance) {
  Tracker tracker;
  const CameraModel camera;
  std::vector<int> ids = tracker.update({at(100, 2000), at(400, 3000, {0, 255, 0})}, camera, 0);
  EXPECT_EQ(ids, (std::vector<int>{1, 2}));
  // Both move a little; given in the other order.
  ids = tracker.update({at(410, 3000, {0, 255, 0}), at(105, 2000)}, camera, 1);
  EXPECT_EQ(ids, (std::vector<int>{2, 1}));
  const TrackedPerson* first = tracker.person(1);
  ASSERT_NE(first, nullptr);
  EXPECT_NEAR(first->distance_cm, 5 * 200.0 / 525.0, 1e-9);  // 5 px at 2 m
  EXPECT_EQ(tracker.people().size(), 2u);
}

TEST(Tracker, FarOrDifferentDetectionsMakeNewPeople) {
  Tracker tracker;
  const CameraModel camera;
  tracker.update({at(100, 2000)}, camera, 0);
  // 2 m away: the distance term alone exceeds the threshold.
  EXPECT_EQ(tracker.update({at(625, 2000)}, camera, 1), std::vector<int>{2});
  // Same place, another colour: the histogram distance of 1 exceeds it.
  EXPECT_EQ(tracker.update({at(100, 2000, {255, 0, 0})}, camera, 2), std::vector<int>{3});
}

TEST(Tracker, SmallestLkhWinsWhenTwoDetectionsMatchOnePerson) {
  Tracker tracker;
  const CameraModel camera;
  tracker.update({at(100, 2000)}, camera, 0);
  const std::vector<int> ids = tracker.update({at(120, 2000), at(104, 2000)}, camera, 1);
  EXPECT_EQ(ids, (std::vector<int>{2, 1}));  // the nearer one keeps id 1, the other is new
}

TEST(Tracker, ForgetsPeopleAfterMaxMissedFrames) {
  TrackingParams params;
  params.max_missed_frames = 3;
  Tracker tracker(params);
  const CameraModel camera;
  tracker.update({at(100, 2000)}, camera, 0);
  EXPECT_EQ(tracker.update({at(100, 2000)}, camera, 3), std::vector<int>{1});
  EXPECT_EQ(tracker.update({at(100, 2000)}, camera, 7), std::vector<int>{2});
}
