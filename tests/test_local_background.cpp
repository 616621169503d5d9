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

namespace {

// A frame of `cols` x `rows` readings: runs of one depth (a wall, a body) with holes, 0 and 65535 now and then.
cv::Mat1w random_depths(int cols, int rows, std::uint32_t seed) {
  cv::Mat1w d(rows, cols);
  std::uint32_t x = seed;
  const auto next = [&x] { return x = x * 1664525u + 1013904223u; };
  std::uint16_t v = 2000;
  for (auto it = d.begin(); it != d.end(); ++it) {
    const std::uint32_t r = next() >> 8;
    if (r % 7 == 0) v = static_cast<std::uint16_t>(500 + (next() >> 8) % 7500);
    *it = r % 23 == 0 ? 0 : r % 97 == 0 ? 65535 : static_cast<std::uint16_t>(v + (r >> 12) % 40);
  }
  return d;
}

// far(x, y) of local_background.hpp's header, computed the plain way: cells' maxima, each side's maximum by a
// loop over its cells.
cv::Mat1w reference_far(const cv::Mat1w& depth, double fx, double reach_mm) {
  const int g = kLocalBackgroundGridPx, gc = (depth.cols + g - 1) / g, gr = (depth.rows + g - 1) / g;
  cv::Mat1w far(depth.size());
  for (int i = 0; i < gr; ++i) {
    std::vector<int> cell(static_cast<std::size_t>(gc), 0);
    for (int r = i * g; r < std::min(depth.rows, i * g + g); ++r) {
      for (int c = 0; c < depth.cols; ++c) cell[static_cast<std::size_t>(c / g)] = std::max<int>(cell[static_cast<std::size_t>(c / g)], depth(r, c));
    }
    for (int j = 0; j < gc; ++j) {
      int behind = 1;
      const int d = cell[static_cast<std::size_t>(j)];
      if (d > 0 && j > 0 && j < gc - 1) {
        const long w = std::max(1L, std::lround(fx * reach_mm / g / d));
        int left = 0, right = 0;
        for (long k = std::max(0L, j - w); k < j; ++k) left = std::max(left, cell[static_cast<std::size_t>(k)]);
        for (long k = j + 1; k <= std::min<long>(gc - 1, j + w); ++k) right = std::max(right, cell[static_cast<std::size_t>(k)]);
        if (std::min(left, right) > 0) behind = std::min(left, right);
      }
      for (int r = i * g; r < std::min(depth.rows, i * g + g); ++r) {
        for (int c = j * g; c < std::min(depth.cols, j * g + g); ++c) far(r, c) = static_cast<std::uint16_t>(behind);
      }
    }
  }
  return far;
}

}  // namespace

// The cell maxima (a vectorised band maximum), the table of reaches and the range maxima give far() of the
// header exactly, on frames whose sizes are no multiple of the cells or of a vector, for three reaches.
TEST(LocalBackground, EqualsTheRuleComputedThePlainWay) {
  for (const cv::Size size : {cv::Size(83, 37), cv::Size(640, 480), cv::Size(21, 5)}) {
    const cv::Mat1w depth = random_depths(size.width, size.height, 11u + static_cast<std::uint32_t>(size.width));
    CameraModel camera = CameraModel::kinect_v1().scaled_to(size.width, size.height);
    for (const double reach_mm : {150.0, 700.0, 3000.0}) {
      const cv::Mat1w far = local_background(depth, camera, reach_mm), expected = reference_far(depth, camera.fx_px, reach_mm);
      EXPECT_EQ(cv::countNonZero(far != expected), 0) << size << " reach " << reach_mm;
    }
  }
}

// foreground_mask and in_front_of (eight or sixteen pixels at a time) against the rule one pixel at a time in
// 64 bits, and in_front_of's layer figures against sums over every pixel, with margins at their limits
// (margin_relative 1: the 32-bit path) and labels beyond the layers (dropped).
TEST(LocalBackground, FrontRuleAndItsLayerFiguresEqualThePlainWay) {
  const cv::Mat1w depth = random_depths(83, 37, 5u), room = random_depths(83, 37, 9u);
  Segmentation segmentation;
  segmentation.labels.create(depth.size());
  for (int l = 1; l <= 3; ++l) segmentation.layers.push_back(DepthLayer{});
  for (std::size_t i = 0; i < segmentation.layers.size(); ++i) segmentation.layers[i].label = static_cast<int>(i + 1);
  for (int r = 0; r < depth.rows; ++r) {
    for (int c = 0; c < depth.cols; ++c) segmentation.labels(r, c) = static_cast<std::uint8_t>(depth(r, c) == 0 ? 0 : (r * 7 + c / 5) % 5);
  }
  for (const BackgroundParams params : {BackgroundParams{}, BackgroundParams{0.0, 0.0}, BackgroundParams{10000.0, 0.5},
                                        BackgroundParams{37.0, 0.123}, BackgroundParams{0.0, 1.0}}) {
    const cv::Mat1b mask = foreground_mask(depth, room, params);
    const Segmentation front = in_front_of(segmentation, depth, room, params);
    const std::uint64_t m = static_cast<std::uint64_t>(std::lround(params.margin_mm)),
                        q = static_cast<std::uint64_t>(std::lround(params.margin_relative * 65536.0));
    std::vector<std::uint64_t> sum(4, 0), count(4, 0), lo(4, 65535), hi(4, 0);
    for (int r = 0; r < depth.rows; ++r) {
      for (int c = 0; c < depth.cols; ++c) {
        const std::uint64_t d = depth(r, c), b = room(r, c), margin = std::max(m, (b * q + 32768) >> 16);
        const bool in_front = d > 0 && (b == 0 || d + margin < b);
        ASSERT_EQ(mask(r, c), in_front ? 255 : 0) << "pixel " << c << "," << r;
        const int label = segmentation.labels(r, c);
        const int expected = in_front && label <= 3 ? label : 0;
        ASSERT_EQ(front.labels(r, c), expected) << "pixel " << c << "," << r;
        if (expected == 0) continue;
        sum[expected] += d, ++count[expected], lo[expected] = std::min(lo[expected], d), hi[expected] = std::max(hi[expected], d);
      }
    }
    for (const DepthLayer& layer : front.layers) {
      const auto k = static_cast<std::size_t>(layer.label);
      EXPECT_EQ(layer.pixel_count, static_cast<std::int64_t>(count[k]));
      if (count[k] == 0) continue;
      EXPECT_EQ(layer.mean_depth_mm, static_cast<double>(sum[k]) / static_cast<double>(count[k]));
      EXPECT_EQ(layer.min_depth_mm, lo[k]);
      EXPECT_EQ(layer.max_depth_mm, hi[k]);
    }
  }
}
