// frame_buffer(): a frame's label images come from a per-thread pool, handed out again only when nobody
// holds them, so a detector that drops each frame's analysis touches no fresh pages, and an analysis still
// held is never written over.
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/core/frame_buffers.hpp"
#include "support/depth_scenes.hpp"

using namespace rdsf;

TEST(FrameBuffers, AReleasedBufferIsHandedOutAgainAHeldOneNever) {
  const cv::Size size(640, 480);
  const std::uint8_t* first = nullptr;
  {
    cv::Mat a = frame_buffer(FrameBuffer::in_front_labels, size, CV_8UC1);
    first = a.data;
    cv::Mat b = frame_buffer(FrameBuffer::in_front_labels, size, CV_8UC1);  // a is held: another
    EXPECT_NE(b.data, a.data);
    cv::Mat shared = a;  // a's buffer held twice over: still busy after a goes
    a.release();
    EXPECT_NE(frame_buffer(FrameBuffer::in_front_labels, size, CV_8UC1).data, first);
  }
  // Everything released: the first buffer again, and each use has its own pool.
  cv::Mat again = frame_buffer(FrameBuffer::in_front_labels, size, CV_8UC1);
  EXPECT_EQ(again.data, first);
  EXPECT_NE(frame_buffer(FrameBuffer::segmentation_labels, size, CV_8UC1).data, first);
  // Another size or type: the size and type asked for.
  const cv::Mat other = frame_buffer(FrameBuffer::in_front_labels, {512, 424}, CV_16UC1);
  EXPECT_EQ(other.size(), cv::Size(512, 424));
  EXPECT_EQ(other.type(), CV_16UC1);
  // A pool whose buffers are all held hands out new images of the right size, as many as asked.
  std::vector<cv::Mat> held;
  for (int i = 0; i < 3 * kFrameBuffersPerUse; ++i) held.push_back(frame_buffer(FrameBuffer::local_far, size, CV_16UC1));
  for (std::size_t i = 0; i < held.size(); ++i) {
    EXPECT_EQ(held[i].size(), size);
    for (std::size_t j = 0; j < i; ++j) EXPECT_NE(held[i].data, held[j].data);
  }
  // Another thread has a pool of its own.
  const std::uint8_t* there = nullptr;
  std::thread([&] { there = frame_buffer(FrameBuffer::in_front_labels, size, CV_8UC1).data; }).join();
  EXPECT_NE(there, again.data);
}

// The analysis of one frame, with the local front's three buffers, is the same whether its buffers held
// another frame's labels before or were fresh; dropping a frame's analysis lets the next reuse them.
TEST(FrameBuffers, AnalysesAreTheSameOnReusedBuffersAndReuseThem) {
  AnalyserParams params;
  params.local_front_reach_cm = 70.0;
  const FrameAnalyser analyser(params);
  DepthFrame a = test::wall_frame(4000);
  test::paint(a, {300, 100, 40, 360}, 2000);
  test::paint(a, {420, 120, 45, 340}, 3700);  // a person 30 cm before the wall
  DepthFrame b = test::wall_frame(3000);
  test::paint(b, {100, 60, 60, 400}, 1500);
  const FrameAnalysis a_held = analyser.analyse(a, false);  // held: b's analysis gets other buffers
  FrameAnalysis b_fresh = analyser.analyse(b, false);
  ASSERT_FALSE(a_held.candidates.empty());
  ASSERT_FALSE(b_fresh.in_front.labels.empty());
  EXPECT_NE(b_fresh.segmentation.labels.data, a_held.segmentation.labels.data);
  const std::uint8_t* b_labels = b_fresh.segmentation.labels.data;
  const std::uint8_t* b_front = b_fresh.in_front.labels.data;
  const std::vector<Candidate> b_candidates = b_fresh.candidates;
  const cv::Mat1b b_segmentation = b_fresh.segmentation.labels.clone(), b_in_front = b_fresh.in_front.labels.clone();
  b_fresh = FrameAnalysis{};  // b's analysis dropped
  const FrameAnalysis again = analyser.analyse(b, false);
  EXPECT_EQ(again.segmentation.labels.data, b_labels);
  EXPECT_EQ(again.in_front.labels.data, b_front);
  EXPECT_EQ(cv::countNonZero(again.segmentation.labels != b_segmentation), 0);
  EXPECT_EQ(cv::countNonZero(again.in_front.labels != b_in_front), 0);
  ASSERT_EQ(again.candidates.size(), b_candidates.size());
  for (std::size_t i = 0; i < b_candidates.size(); ++i) EXPECT_EQ(again.candidates[i].strict_box, b_candidates[i].strict_box);
  // a's analysis, held all along, was never written over.
  const FrameAnalysis a_again = analyser.analyse(a, false);
  EXPECT_EQ(cv::countNonZero(a_again.segmentation.labels != a_held.segmentation.labels), 0);
  EXPECT_EQ(cv::countNonZero(a_again.in_front.labels != a_held.in_front.labels), 0);
}
