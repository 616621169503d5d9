#include <gtest/gtest.h>

#include <optional>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/candidates/column_heights.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/synth/synth_sequence.hpp"
#include "support/depth_scenes.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

FrameAnalysis analyse(const DepthFrame& frame, AnalyserParams params = {}) {
  return FrameAnalyser(params).analyse(frame, false);
}

const Candidate* find_at_depth(const std::vector<Candidate>& candidates, double depth_mm, int highest_column) {
  for (const Candidate& c : candidates) {
    if (std::abs(c.layer_depth_mm - depth_mm) < 1 && c.highest_column == highest_column) return &c;
  }
  return nullptr;
}

}  // namespace

// A gap of missing readings only (label 0) is crossed up to hole_gap_px rows; one holding a pixel of a
// farther layer, or longer than the limit, still breaks the run; nearer pixels in a gap are the occlusion
// gap's (not crossed here: no occlusion limit).
TEST(ColumnRuns, HoleGapsOfMissingReadingsOnlyAreCrossedUpToTheirLimit) {
  cv::Mat1b labels = cv::Mat1b::zeros(60, 4);
  for (int c = 0; c < 4; ++c) {
    labels(cv::Rect(c, 0, 1, 10)).setTo(2);   // rows 0..9 of layer 2
    labels(cv::Rect(c, 22, 1, 30)).setTo(2);  // rows 22..51 after a gap of 12 rows
  }
  labels(15, 2) = 3;                          // column 2: a farther pixel in the gap
  labels(15, 3) = 1;                          // column 3: a nearer pixel in the gap
  const std::vector<int> holes = {0, 0, 12, 0};
  const auto crossed = column_runs(labels, 3, 3, {}, holes);
  EXPECT_EQ(crossed[2][0].top, 0);   // missing readings only, 12 rows <= 12: one run 0..51
  EXPECT_EQ(crossed[2][0].bottom, 51);
  EXPECT_EQ(crossed[2][2].top, 22);  // a farther layer's pixel in the gap: broken
  EXPECT_EQ(crossed[2][3].top, 22);  // a nearer one: the occlusion gap's rule, limit 0 here: broken
  const auto shorter = column_runs(labels, 3, 3, {}, {0, 0, 11, 0});
  EXPECT_EQ(shorter[2][0].top, 22);  // 12 rows > 11
  const auto off = column_runs(labels, 3, 3);
  EXPECT_EQ(off[2][0].top, 22);      // no hole limit: k alone
  EXPECT_EQ(off[2][0].bottom, 51);
}

TEST(ColumnRuns, LongestRunToleratesGapsOfK) {
  cv::Mat1b labels = cv::Mat1b::zeros(40, 3);
  labels(cv::Rect(0, 2, 1, 5)).setTo(1);    // column 0: rows 2..6
  labels(cv::Rect(0, 10, 1, 20)).setTo(1);  // rows 10..29 after a gap of 3 rows -> one run 2..29 with k=3
  labels(cv::Rect(1, 0, 1, 4)).setTo(1);    // column 1: rows 0..3, gap of 5, rows 9..10
  labels(cv::Rect(1, 9, 1, 2)).setTo(1);
  const auto runs = column_runs(labels, 1, 3);
  EXPECT_EQ(runs[1][0].top, 2);
  EXPECT_EQ(runs[1][0].bottom, 29);
  EXPECT_EQ(runs[1][1].top, 0);  // the gap of 5 > k breaks it: 0..3 is longer than 9..10
  EXPECT_EQ(runs[1][1].bottom, 3);
  EXPECT_EQ(runs[1][2].length(), 0);
}

// A person at 2 m whose body a band of missing readings crosses (dark trousers): each half is 160 rows,
// 61 cm, under far_height (90 cm), so the default runs (gaps of k = 6 rows) give no candidate; with
// hole_gap the run crosses the 40-row band (15 cm at 2 m) and the person is one candidate, head to feet. A
// band holding the wall's readings (the person's legs apart, the wall seen between them) is not crossed.
TEST(CandidateFinder, HoleGapJoinsAPersonCutByMissingReadings) {
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {300, 100, 40, 360}, 2000);
  test::paint(frame, {300, 260, 40, 40}, 0);
  AnalyserParams on;
  on.candidates.hole_gap_cm = 20;  // 52 rows at 2 m
  EXPECT_EQ(find_at_depth(analyse(frame).candidates, 2000, 320), nullptr);
  const FrameAnalysis crossed = analyse(frame, on);
  const Candidate* person = find_at_depth(crossed.candidates, 2000, 320);
  ASSERT_NE(person, nullptr);
  EXPECT_EQ(person->strict_box.y, 100);
  EXPECT_EQ(person->strict_box.height, 360);
  on.candidates.hole_gap_cm = 10;  // 26 rows < 40
  EXPECT_EQ(find_at_depth(analyse(frame, on).candidates, 2000, 320), nullptr);
  on.candidates.hole_gap_cm = 20;
  test::paint(frame, {300, 260, 40, 40}, 4000);
  EXPECT_EQ(find_at_depth(analyse(frame, on).candidates, 2000, 320), nullptr);
}

TEST(CandidateFinder, PersonBeforeWall) {
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {300, 100, 40, 360}, 2000);
  const FrameAnalysis a = analyse(frame);
  // The person, and the wall left and right of it (the wall behind the person is too short there).
  ASSERT_EQ(a.candidates.size(), 3u);
  const Candidate& person = a.candidates[0];
  EXPECT_DOUBLE_EQ(person.layer_depth_mm, 2000.0);
  EXPECT_EQ(person.highest_column, 320);  // middle of columns 300..339
  EXPECT_EQ(person.strict_box, cv::Rect(230, 100, 180, 360));  // height 360, width 180 about column 320
  EXPECT_EQ(person.window_unclipped, cv::Rect(208, 55, 225, 450));  // +25% both ways about the centre
  EXPECT_EQ(person.window, cv::Rect(208, 55, 225, 425));             // clipped at the bottom edge
  EXPECT_NEAR(person.height_cm, 360 * 2000.0 / 525.0 / 10.0, 1e-9);
  EXPECT_NEAR(person.width_cm, 40 * 2000.0 / 525.0 / 10.0, 1e-9);
  // Crop: only the layer's pixels; columns 26..37 and rows 13..114 of the 64x128 crop sample the block.
  ASSERT_EQ(person.depth_crop.size(), cv::Size(64, 128));
  EXPECT_EQ(cv::countNonZero(person.depth_crop), 12 * 102);
  EXPECT_EQ(person.depth_crop(13, 26), 2000);
  EXPECT_EQ(person.depth_crop(114, 37), 2000);
  EXPECT_EQ(person.depth_crop(12, 26), 0);
  EXPECT_EQ(person.depth_crop(13, 25), 0);
  EXPECT_EQ(person.depth_crop(115, 37), 0);
  EXPECT_EQ(person.depth_crop(13, 38), 0);
  EXPECT_TRUE(person.colour_crop.empty());
  // The wall pieces: full height at 4000 mm.
  EXPECT_EQ(a.candidates[1].strict_box, cv::Rect(30, 0, 240, 480));
  EXPECT_EQ(a.candidates[2].strict_box, cv::Rect(370, 0, 240, 480));
}

// The strict box is half as wide as tall in metres: with pixels 1.25 times as wide as tall in the scene
// (fx = 1.25 fy), 360 rows make lround(360 * 1.25 / 2) = 225 columns, the window 281 x 450 about the same
// centre: the crop shows the person as wide, in metres, as on square pixels.
TEST(CandidateFinder, StrictBoxIsHalfAsWideAsTallInMetresOnNonSquarePixels) {
  DepthFrame frame = test::wall_frame(4000);
  frame.camera.fx_px = 1.25 * frame.camera.fy_px;
  test::paint(frame, {290, 100, 61, 360}, 2000);  // 61 columns: 18.6 cm at 2 m
  const FrameAnalysis a = analyse(frame);
  const Candidate* person = find_at_depth(a.candidates, 2000, 320);
  ASSERT_NE(person, nullptr);
  EXPECT_EQ(person->strict_box, cv::Rect(208, 100, 225, 360));
  EXPECT_EQ(person->window_unclipped.size(), cv::Size(281, 450));
  EXPECT_NEAR(person->width_cm, 61 * 2000.0 / (1.25 * 525.0) / 10.0, 1e-9);
  // 61 of the window's 281 columns: 14 of the crop's 64 (17 of 64 in a 225-column window, height_px / 2).
  ASSERT_EQ(person->depth_crop.size(), cv::Size(64, 128));
  EXPECT_NEAR(cv::countNonZero(person->depth_crop.row(64)), 61.0 * 64 / 281, 1.0);
}

TEST(CandidateFinder, TwoPeopleAtOneDepth) {
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {150, 100, 40, 360}, 2000);
  test::paint(frame, {400, 60, 40, 400}, 2000);  // the taller one
  const FrameAnalysis a = analyse(frame);
  ASSERT_EQ(a.segmentation.layers.size(), 2u);
  const Candidate* left = find_at_depth(a.candidates, 2000, 170);
  const Candidate* right = find_at_depth(a.candidates, 2000, 420);
  ASSERT_NE(left, nullptr);
  ASSERT_NE(right, nullptr);
  EXPECT_EQ(left->strict_box, cv::Rect(80, 100, 180, 360));
  EXPECT_EQ(right->strict_box, cv::Rect(320, 60, 200, 400));
  int at_2000 = 0;
  for (const Candidate& c : a.candidates) at_2000 += std::abs(c.layer_depth_mm - 2000) < 1 ? 1 : 0;
  EXPECT_EQ(at_2000, 2);
}

TEST(CandidateFinder, MissingReadingsInsideThePersonAreTolerated) {
  DepthFrame clean = test::wall_frame(4000);
  test::paint(clean, {300, 100, 40, 360}, 2000);
  DepthFrame noisy = clean;
  noisy.depth_mm = clean.depth_mm.clone();
  // Zeros scattered through the person, never more than k rows in a column.
  for (int y = 100; y < 460; y += 4) {
    for (int x = 300 + (y % 5); x < 340; x += 5) noisy.depth_mm(y, x) = 0;
  }
  const FrameAnalysis a = analyse(noisy);
  const Candidate* person = nullptr;
  for (const Candidate& c : a.candidates) {
    if (std::abs(c.layer_depth_mm - 2000) < 1) person = &c;
  }
  ASSERT_NE(person, nullptr);
  // Same height; the highest point's column may move by a pixel where a zero hits the top row.
  EXPECT_EQ(person->strict_box.y, 100);
  EXPECT_EQ(person->strict_box.height, 360);
  EXPECT_NEAR(person->strict_box.x, 230, 2);
  // The zeros stay zeros in the crop: no blending of missing readings into depths.
  for (int v = 0; v < 128; ++v) {
    for (int u = 0; u < 64; ++u) {
      const auto d = person->depth_crop(v, u);
      EXPECT_TRUE(d == 0 || d == 2000);
    }
  }
}

TEST(CandidateFinder, PersonAtTheImageBorder) {
  DepthFrame centred = test::wall_frame(4000);
  test::paint(centred, {300, 100, 40, 360}, 2000);
  DepthFrame border = test::wall_frame(4000);
  test::paint(border, {0, 100, 40, 360}, 2000);
  const FrameAnalysis a = analyse(border);
  const Candidate* person = find_at_depth(a.candidates, 2000, 20);
  ASSERT_NE(person, nullptr);
  EXPECT_EQ(person->strict_box, cv::Rect(0, 100, 110, 360));  // (-70, 100, 180, 360) clipped
  EXPECT_EQ(person->window_unclipped, cv::Rect(-93, 55, 225, 450));
  EXPECT_EQ(person->window, cv::Rect(0, 55, 132, 425));
  // Outside the image reads 0, so the crop shows the person where a centred person appears.
  const FrameAnalysis centred_analysis = analyse(centred);
  const Candidate* reference = find_at_depth(centred_analysis.candidates, 2000, 320);
  ASSERT_NE(reference, nullptr);
  EXPECT_EQ(cv::norm(person->depth_crop, reference->depth_crop, cv::NORM_INF), 0.0);
}

TEST(CandidateFinder, ShortAndNarrowObjectsAreNotCandidates) {
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {100, 300, 60, 100}, 2000);  // 100 rows at 2 m = 38 cm: below 90 cm
  test::paint(frame, {400, 100, 10, 360}, 2000);  // 10 columns at 2 m = 3.8 cm: narrower than 10 cm
  const FrameAnalysis a = analyse(frame);
  for (const Candidate& c : a.candidates) EXPECT_NEAR(c.layer_depth_mm, 4000.0, 1.0);
}

TEST(CandidateFinder, StrictAndRelaxedThresholdHeight) {
  // A 70 cm tall object at 2 m: fails strict (90 cm beyond 1.5 m), passes relaxed (50 cm).
  DepthFrame frame = test::wall_frame(4000);
  const int rows = static_cast<int>(70.0 * 10.0 * 525.0 / 2000.0) + 1;
  test::paint(frame, {300, 470 - rows, 60, rows}, 2000);
  AnalyserParams strict;
  AnalyserParams relaxed;
  relaxed.candidates.mode = HeightMode::relaxed;
  EXPECT_EQ(find_at_depth(analyse(frame, strict).candidates, 2000, 330), nullptr);
  EXPECT_NE(find_at_depth(analyse(frame, relaxed).candidates, 2000, 330), nullptr);
  EXPECT_DOUBLE_EQ(strict.candidates.threshold_height_cm(1400), 50.0);
  EXPECT_DOUBLE_EQ(strict.candidates.threshold_height_cm(1600), 90.0);
  EXPECT_DOUBLE_EQ(relaxed.candidates.threshold_height_cm(1600), 50.0);
}

// BorderCutParams: a person the image cuts at the bottom shows less than threshold_height; a column whose
// run reaches the image's bottom twentieth passes at border.height_cm when it is a third of the image tall
// and upright. A low box on the image's bottom is no such person.
TEST(CandidateFinder, PeopleTheImageCutsAreCandidates) {
  DepthFrame frame = test::wall_frame(4000);
  const cv::Rect person(300, 280, 80, 200);  // 200 rows at 2 m = 76 cm shown: under the far 90 cm
  test::paint(frame, person, 2000);
  test::paint(frame, {60, 380, 120, 100}, 2000);  // a box of 100 rows (38 cm) on the bottom: too short a run
  AnalyserParams on, off;  // off: the default
  on.candidates.border.height_cm = 25;
  const AnalyserParams thesis = thesis_params(on);
  // The candidate at 2 m over column x, copied out of its analysis.
  const auto at = [](const DepthFrame& f, const AnalyserParams& p, int x) -> std::optional<Candidate> {
    for (const Candidate& c : analyse(f, p).candidates) {
      if (std::abs(c.layer_depth_mm - 2000) < 1 && c.strict_box.x <= x && x < c.strict_box.x + c.strict_box.width) return c;
    }
    return std::nullopt;
  };
  const auto found = [&](const AnalyserParams& p, int x) { return at(frame, p, x); };
  const std::optional<Candidate> cut = found(on, 340);
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(cut->strict_box.y, person.y);
  EXPECT_EQ(cut->strict_box.y + cut->strict_box.height, person.y + person.height);  // down to the image's bottom
  EXPECT_FALSE(found(off, 340).has_value());
  EXPECT_FALSE(found(thesis, 340).has_value());  // the thesis's threshold_height alone
  EXPECT_FALSE(found(on, 120).has_value());
  // The same person lifted off the image's bottom (a floating torso) is no person the image cuts.
  DepthFrame lifted = test::wall_frame(4000);
  test::paint(lifted, person - cv::Point(0, 60), 2000);
  EXPECT_FALSE(at(lifted, on, 340).has_value());
  EXPECT_DOUBLE_EQ(thesis.candidates.border.height_cm, 0.0);
}

TEST(CandidateFinder, ColourCropIsMaskedByTheLayer) {
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {300, 100, 40, 360}, 2000);
  frame.bgr = cv::Mat3b(480, 640, cv::Vec3b(10, 20, 30));
  frame.bgr(cv::Rect(300, 100, 40, 360)).setTo(cv::Scalar(200, 100, 50));
  const FrameAnalysis a = analyse(frame);
  const Candidate* person = find_at_depth(a.candidates, 2000, 320);
  ASSERT_NE(person, nullptr);
  ASSERT_EQ(person->colour_crop.size(), cv::Size(64, 128));
  EXPECT_EQ(person->colour_crop(50, 30), cv::Vec3b(200, 100, 50));
  EXPECT_EQ(person->colour_crop(50, 5), cv::Vec3b(0, 0, 0));  // the wall is another layer: black
}

// CropColour::later leaves the colour crops empty and everything else as it was; cut_colour_crop() then
// cuts the same pixels, for windows inside the image and across its borders (synthetic rooms, 1-4 people).
TEST(CandidateFinder, ColourCropCutLaterIsTheSame) {
  synth::SynthParams p = synth::people_scene(12, 1, 4, 5);
  p.rgb = true;
  p.clip_frames = 3;
  const FrameAnalyser analyser;
  int candidates = 0, crossing_border = 0;
  for (const DepthFrame& frame : test::synthetic_frames(p)) {
    const FrameAnalysis now = analyser.analyse(frame, false, CropColour::cut);
    FrameAnalysis later = analyser.analyse(frame, false, CropColour::later);
    ASSERT_EQ(now.candidates.size(), later.candidates.size());
    for (std::size_t c = 0; c < now.candidates.size(); ++c) {
      Candidate& x = later.candidates[c];
      EXPECT_TRUE(x.colour_crop.empty());
      EXPECT_EQ(x.window_unclipped, now.candidates[c].window_unclipped);
      EXPECT_EQ(cv::norm(x.depth_crop, now.candidates[c].depth_crop, cv::NORM_INF), 0.0);
      cut_colour_crop(frame, later.segmentation.labels, x);
      ASSERT_EQ(x.colour_crop.size(), cv::Size(64, 128));
      EXPECT_EQ(cv::norm(x.colour_crop, now.candidates[c].colour_crop, cv::NORM_INF), 0.0) << frame.name;
      ++candidates;
      crossing_border += (x.window_unclipped & cv::Rect(0, 0, 640, 480)) != x.window_unclipped ? 1 : 0;
    }
  }
  EXPECT_GT(candidates, 20);
  EXPECT_GT(crossing_border, 0);
  // Without colour in the frame there is none to cut.
  DepthFrame grey = test::wall_frame(4000);
  test::paint(grey, {300, 100, 40, 360}, 2000);
  FrameAnalysis a = analyser.analyse(grey, false, CropColour::later);
  ASSERT_FALSE(a.candidates.empty());
  cut_colour_crop(grey, a.segmentation.labels, a.candidates[0]);
  EXPECT_TRUE(a.candidates[0].colour_crop.empty());
}

TEST(CandidateFinder, IntersectionOverUnion) {
  EXPECT_DOUBLE_EQ(iou({0, 0, 10, 10}, {0, 0, 10, 10}), 1.0);
  EXPECT_DOUBLE_EQ(iou({0, 0, 10, 10}, {5, 0, 10, 10}), 50.0 / 150.0);
  EXPECT_DOUBLE_EQ(iou({0, 0, 10, 10}, {20, 20, 5, 5}), 0.0);
  EXPECT_DOUBLE_EQ(iou({0, 0, 0, 0}, {0, 0, 0, 0}), 0.0);
}
