// The per-frame local background (segmentation/local_background.hpp) and the candidates it adds through
// AnalyserParams::local_front_reach_cm: the rule on a row, its edges, a person against a wall found
// without any learned background, a free-standing person unchanged, the switch off by default and under
// --thesis, and bad input.
#include <gtest/gtest.h>

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/segmentation/background_model.hpp"
#include "rdsf/segmentation/local_background.hpp"
#include "support/depth_scenes.hpp"
#include "support/pipeline_runs.hpp"

using namespace rdsf;

namespace {

constexpr int kWallMm = 3000;
constexpr int kPersonMm = 2750;        // 25 cm in front of the wall: one depth layer with it
const cv::Rect kPerson(300, 100, 60, 330);  // 1.73 m tall at 2.75 m

DepthFrame person_frame(const cv::Rect& body, int depth_mm) {
  DepthFrame frame = test::wall_frame(kWallMm);
  test::paint(frame, {body.x + body.width / 2 - 12, body.y, 24, 40}, depth_mm);  // head
  test::paint(frame, {body.x, body.y + 40, body.width, body.height - 40}, depth_mm);
  return frame;
}

AnalyserParams local_front(double reach_cm) {
  AnalyserParams params;
  params.local_front_reach_cm = reach_cm;
  return params;
}

}  // namespace

TEST(LocalBackground, APersonBeforeAWallHasTheWallBehindAndTheWallHasItself) {
  const DepthFrame frame = person_frame(kPerson, kPersonMm);
  const cv::Mat1w far = local_background(frame.depth_mm, frame.camera, 700.0);
  ASSERT_EQ(far.size(), frame.depth_mm.size());
  EXPECT_EQ(far(kPerson.y + 100, kPerson.x + 30), kWallMm);  // the body: the wall on both sides
  EXPECT_EQ(far(kPerson.y + 100, 100), kWallMm);            // the wall: itself
  const cv::Mat1b front = foreground_mask(frame.depth_mm, far, BackgroundParams{});
  EXPECT_EQ(front(kPerson.y + 100, kPerson.x + 30), 255);
  EXPECT_EQ(front(kPerson.y + 100, 100), 0);
  EXPECT_EQ(front(20, kPerson.x + 30), 0);  // above the head: the wall
}

TEST(LocalBackground, NoReadingOrNoSideMeansNothingIsInFront) {
  DepthFrame frame = person_frame(kPerson, kPersonMm);
  test::paint(frame, {0, 0, 640, 8}, 0);  // the first grid row without readings
  const cv::Mat1w far = local_background(frame.depth_mm, frame.camera, 700.0);
  EXPECT_EQ(far(2, 320), 1);    // a pixel without a reading: 1 mm, nothing is nearer
  EXPECT_EQ(far(200, 0), 1);    // the first column has no left side
  EXPECT_EQ(far(200, 639), 1);  // the last grid column has no right side
  // A reach too short to leave the body: its own depth on both sides, not in front.
  const cv::Mat1w short_reach = local_background(frame.depth_mm, frame.camera, 50.0);
  EXPECT_EQ(short_reach(kPerson.y + 100, kPerson.x + 30), kPersonMm);
}

TEST(LocalBackground, BadReachOrCameraIsAnError) {
  const DepthFrame frame = test::wall_frame(kWallMm);
  EXPECT_THROW(local_background(frame.depth_mm, frame.camera, 0.0), Error);
  CameraModel broken = frame.camera;
  broken.fx_px = 0;
  EXPECT_THROW(local_background(frame.depth_mm, broken, 700.0), Error);
}

TEST(LocalBackground, PersonAgainstAWallIsACandidateWithoutALearnedBackground) {
  const DepthFrame frame = person_frame(kPerson, kPersonMm);
  const FrameAnalysis off = FrameAnalyser().analyse(frame, false);
  EXPECT_TRUE(std::none_of(off.candidates.begin(), off.candidates.end(), [](const Candidate& c) { return c.foreground; }));
  EXPECT_TRUE(off.in_front.labels.empty());
  const FrameAnalysis on = FrameAnalyser(local_front(70)).analyse(frame, false);
  const Candidate* person = nullptr;
  for (const Candidate& c : on.candidates) {
    if (c.foreground && (person == nullptr || iou(c.strict_box, kPerson) > iou(person->strict_box, kPerson))) person = &c;
  }
  ASSERT_NE(person, nullptr);
  EXPECT_EQ(person->strict_box.y, kPerson.y);  // head to feet, not the waist
  EXPECT_EQ(person->strict_box.height, kPerson.height);
  EXPECT_EQ(person->strict_box.x + person->strict_box.width / 2, kPerson.x + kPerson.width / 2);  // centred on the body
  EXPECT_NEAR(person->layer_depth_mm, kPersonMm, 1.0);
  double highest = 0;
  cv::minMaxLoc(person->depth_crop, nullptr, &highest);
  EXPECT_EQ(highest, kPersonMm);  // the crop holds the person's pixels only, no wall
  ASSERT_GE(on.candidates.size(), off.candidates.size());
  for (std::size_t i = 0; i < off.candidates.size(); ++i) EXPECT_EQ(on.candidates[i].strict_box, off.candidates[i].strict_box);
}

TEST(LocalBackground, AFreeStandingPersonGetsNoDuplicate) {
  const cv::Rect body(300, 40, 90, 420);
  const DepthFrame frame = person_frame(body, 2000);  // 1 m in front of the wall: a layer of its own
  const FrameAnalysis off = FrameAnalyser().analyse(frame, false);
  const FrameAnalysis on = FrameAnalyser(local_front(70)).analyse(frame, false);
  ASSERT_EQ(on.candidates.size(), off.candidates.size());
  for (std::size_t i = 0; i < off.candidates.size(); ++i) EXPECT_EQ(on.candidates[i].fitted_box, off.candidates[i].fitted_box);
}

TEST(LocalBackground, OffByDefaultAndUnderTheThesis) {
  EXPECT_EQ(AnalyserParams{}.local_front_reach_cm, 0.0);
  EXPECT_EQ(thesis_params(local_front(70)).local_front_reach_cm, 0.0);
}

// Each thread fills a buffer of its own (frame_analyser.cpp): frames of two sizes, interleaved, on 1 and 3
// threads give the same candidates in the same order.
TEST(LocalBackground, ResultsDoNotDependOnTheThreadCountOrTheFrameSizes) {
  std::vector<DepthFrame> frames;
  for (int i = 0; i < 9; ++i) {
    DepthFrame f = person_frame({40 + 60 * i, 100, 60, 330}, i % 2 == 0 ? kPersonMm : 1800);
    if (i % 3 == 2) {  // a smaller sensor now and then: the buffer must follow the frame's size
      cv::Mat1w half;
      cv::resize(f.depth_mm, half, {320, 240}, 0, 0, cv::INTER_NEAREST);
      f.depth_mm = half;
      f.camera = f.camera.scaled_to(320, 240);
    }
    f.index = i;
    f.name = std::to_string(i);
    frames.push_back(f);
  }
  PipelineParams params;
  params.analyser.local_front_reach_cm = 70;
  const test::CandidateBoxes one = test::candidate_boxes(params, frames, 1);
  ASSERT_EQ(one.size(), frames.size());
  const std::size_t added = test::foreground_count(one);
  EXPECT_GE(added, 3u);  // the people against the wall
  EXPECT_EQ(test::candidate_boxes(params, frames, 3), one);
}
