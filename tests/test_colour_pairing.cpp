// rdsf_people's pairing of depth frames with colour images by stamp (ros/colour_pairing.hpp; no ROS in it,
// so it is tested without ROS).
#include <gtest/gtest.h>

#include "ros/colour_pairing.hpp"

namespace rdsf {
namespace {

DepthFrame depth_at(std::int64_t stamp_us) {
  DepthFrame f;
  f.depth_mm = cv::Mat1w(4, 4, std::uint16_t{1000});
  f.timestamp_us = stamp_us;
  return f;
}
cv::Mat3b colour() { return cv::Mat3b(4, 4, cv::Vec3b(1, 2, 3)); }

constexpr std::int64_t kGap = 15000;

TEST(ColourPairing, ColourBeforeDepthPairsAtOnce) {
  ColourPairing pairing(kGap);
  EXPECT_TRUE(pairing.add_colour(1000000, colour()).empty());
  const std::vector<PairedFrame> out = pairing.add_depth(depth_at(1000000 + 2000));
  ASSERT_EQ(out.size(), 1U);
  EXPECT_FALSE(out[0].frame.bgr.empty());
  EXPECT_EQ(out[0].gap_us, 2000);
}

TEST(ColourPairing, DepthWaitsForItsColour) {
  ColourPairing pairing(kGap);
  ASSERT_TRUE(pairing.add_colour(0, colour()).empty());
  ASSERT_EQ(pairing.add_depth(depth_at(0)).size(), 1U);
  EXPECT_TRUE(pairing.add_depth(depth_at(33333)).empty());  // its colour is still to come
  const std::vector<PairedFrame> out = pairing.add_colour(33333, colour());
  ASSERT_EQ(out.size(), 1U);
  EXPECT_EQ(out[0].frame.timestamp_us, 33333);
  EXPECT_EQ(out[0].gap_us, 0);
}

TEST(ColourPairing, AFrameWithoutColourGoesOnWithTheNextMessage) {
  ColourPairing pairing(kGap);
  ASSERT_TRUE(pairing.add_colour(0, colour()).empty());
  ASSERT_EQ(pairing.add_depth(depth_at(0)).size(), 1U);
  EXPECT_TRUE(pairing.add_depth(depth_at(33333)).empty());
  // The next frame's colour arrives first: frame 33333 has none.
  std::vector<PairedFrame> out = pairing.add_colour(66666, colour());
  ASSERT_EQ(out.size(), 1U);
  EXPECT_EQ(out[0].frame.timestamp_us, 33333);
  EXPECT_TRUE(out[0].frame.bgr.empty());
  EXPECT_EQ(out[0].gap_us, -1);
  out = pairing.add_depth(depth_at(66666));
  ASSERT_EQ(out.size(), 1U);
  EXPECT_EQ(out[0].gap_us, 0);
  // Or the next depth frame arrives first: the waiting one goes on without colour, the new one waits.
  EXPECT_TRUE(pairing.add_depth(depth_at(100000)).empty());
  out = pairing.add_depth(depth_at(133333));
  ASSERT_EQ(out.size(), 1U);
  EXPECT_EQ(out[0].frame.timestamp_us, 100000);
  EXPECT_TRUE(out[0].frame.bgr.empty());
  out = pairing.flush();
  ASSERT_EQ(out.size(), 1U);
  EXPECT_EQ(out[0].frame.timestamp_us, 133333);
}

TEST(ColourPairing, ColourOutsideTheGapIsNotAPair) {
  ColourPairing pairing(kGap);
  ASSERT_TRUE(pairing.add_colour(0, colour()).empty());
  EXPECT_TRUE(pairing.add_depth(depth_at(kGap + 1)).empty());  // too far from 0; its own may come
  const std::vector<PairedFrame> out = pairing.flush();
  ASSERT_EQ(out.size(), 1U);
  EXPECT_TRUE(out[0].frame.bgr.empty());
}

TEST(ColourPairing, WithoutAnyColourFramesStopWaitingAfterTheStaleTime) {
  ColourPairing pairing(kGap, 1000000);
  EXPECT_TRUE(pairing.add_depth(depth_at(0)).empty());  // the colour may still come
  EXPECT_EQ(pairing.add_depth(depth_at(33333)).size(), 1U);  // releases frame 0 only
  std::vector<PairedFrame> out = pairing.add_depth(depth_at(2000000));  // 2 s without colour: no waiting
  ASSERT_EQ(out.size(), 2U);
  EXPECT_EQ(out[1].frame.timestamp_us, 2000000);
  EXPECT_TRUE(out[1].frame.bgr.empty());
}

TEST(ColourPairing, StampsThatStartAgainCostOneFrameItsColour) {
  ColourPairing pairing(kGap);
  for (std::int64_t t : {0, 33333, 66666}) {
    ASSERT_TRUE(pairing.add_colour(t, colour()).empty());
    ASSERT_EQ(pairing.add_depth(depth_at(t)).size(), 1U);
  }
  // The bag loops: the stamps are 0, 33333, ... again.
  int with_colour = 0;
  for (std::int64_t t : {0, 33333, 66666}) {
    std::vector<PairedFrame> out = pairing.add_depth(depth_at(t));
    std::vector<PairedFrame> more = pairing.add_colour(t, colour());
    out.insert(out.end(), more.begin(), more.end());
    for (const PairedFrame& p : out) with_colour += p.frame.bgr.empty() ? 0 : 1;
  }
  const std::vector<PairedFrame> rest = pairing.flush();
  EXPECT_TRUE(rest.empty());
  EXPECT_GE(with_colour, 2);
}

// --colour-wait false: a depth frame whose colour comes after it (as from a driver or rosbag play) goes on at
// once, with the previous frame's colour when that lies within the gap, and is never held back.
TEST(ColourPairing, WithoutWaitingADepthFrameTakesTheColourAlreadyThere) {
  constexpr std::int64_t kFrame = 33333;
  ColourPairing pairing(40000, 1000000, 8, ColourWait::never);
  ASSERT_EQ(pairing.add_depth(depth_at(0)).size(), 1U);  // no colour yet: at once, without
  for (std::int64_t i = 1; i <= 4; ++i) {
    ASSERT_TRUE(pairing.add_colour((i - 1) * kFrame, colour()).empty());  // the previous frame's colour
    const std::vector<PairedFrame> out = pairing.add_depth(depth_at(i * kFrame));
    ASSERT_EQ(out.size(), 1U);
    EXPECT_EQ(out[0].frame.timestamp_us, i * kFrame);
    EXPECT_FALSE(out[0].frame.bgr.empty());
    EXPECT_EQ(out[0].gap_us, kFrame);
  }
  // The same stream with waiting: every frame waits for, and takes, its own colour.
  ColourPairing waiting(40000);
  ASSERT_EQ(waiting.add_depth(depth_at(0)).size(), 0U);
  const std::vector<PairedFrame> paired = waiting.add_colour(0, colour());
  ASSERT_EQ(paired.size(), 1U);
  EXPECT_EQ(paired[0].gap_us, 0);
}

// A frame whose colour came first takes it; the next frame, whose colour comes late, takes the same one.
TEST(ColourPairing, WithoutWaitingTheColourTakenServesTheNextFrameToo) {
  ColourPairing pairing(40000, 1000000, 8, ColourWait::never);
  ASSERT_TRUE(pairing.add_colour(0, colour()).empty());
  std::vector<PairedFrame> out = pairing.add_depth(depth_at(0));
  ASSERT_EQ(out.size(), 1U);
  EXPECT_EQ(out[0].gap_us, 0);
  out = pairing.add_depth(depth_at(33333));
  ASSERT_EQ(out.size(), 1U);
  EXPECT_FALSE(out[0].frame.bgr.empty());
  EXPECT_EQ(out[0].gap_us, 33333);
}

TEST(ColourPairing, WithoutWaitingAColourTooOldIsNotTaken) {
  ColourPairing pairing(kGap, 1000000, 8, ColourWait::never);
  ASSERT_TRUE(pairing.add_colour(0, colour()).empty());
  const std::vector<PairedFrame> out = pairing.add_depth(depth_at(33333));
  ASSERT_EQ(out.size(), 1U);
  EXPECT_TRUE(out[0].frame.bgr.empty());
  EXPECT_EQ(out[0].gap_us, -1);
  EXPECT_TRUE(pairing.add_colour(33333, colour()).empty());  // nothing waits, so nothing comes out
  EXPECT_TRUE(pairing.flush().empty());
}

}  // namespace
}  // namespace rdsf
