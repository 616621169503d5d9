// The passing columns and spans of LayerShape (layer_shape.hpp) and the fitted extent of fit_object()
// (object_fit.hpp), the heads of object_heads.hpp and the cuts of object_cut.hpp, on a hand-built layer at 5,250 mm, where with fx = fy = 525 one pixel is one centimetre.
#include <gtest/gtest.h>

#include "rdsf/candidates/object_cut.hpp"
#include "rdsf/candidates/object_fit.hpp"
#include "rdsf/candidates/object_heads.hpp"
#include "rdsf/candidates/narrow_person.hpp"

namespace rdsf {
namespace {

// 100 x 40: a body of layer 1 in columns 10..14 (rows 20..79, depth 5250) and an arm beside it in columns
// 15..19 (rows 30..40; column 17 also rows 10..29), then columns 20..23 empty, column 24 at 5,250 + 500 mm
// (too deep a step), columns 30..32 another body. Heights: 50 cm pass (relaxed mode), the arm's do not.
struct Layer {
  cv::Mat1b labels = cv::Mat1b::zeros(100, 40);
  cv::Mat1w depth = cv::Mat1w::zeros(100, 40);
  std::vector<ColumnRun> runs = std::vector<ColumnRun>(40);
  CameraModel camera;
  CandidateParams params;
  void fill(int c, int top, int bottom, int depth_mm, int label = 1) {
    for (int y = top; y <= bottom; ++y) labels(y, c) = static_cast<std::uint8_t>(label), depth(y, c) = static_cast<std::uint16_t>(depth_mm);
    if (label == 1) runs[static_cast<std::size_t>(c)] = {top, bottom};
  }
  Layer() {
    for (int c = 10; c <= 14; ++c) fill(c, 20, 79, 5250);
    for (int c = 15; c <= 19; ++c) fill(c, 30, 40, 5250);
    fill(17, 10, 40, 5250);
    fill(24, 30, 40, 5750);
    for (int c = 30; c <= 32; ++c) fill(c, 20, 79, 5250);
    params.mode = HeightMode::relaxed;
    params.near_height_cm = 50.0;
    params.height_at_column_depth = false;
    params.fit.reach_cm = 60.0;
    params.fit.depth_step_mm = 150.0;
    params.column_gap = 6;
    params.fit.occlusion_gap_cm = 0.0;
  }
  LayerView view() const { return {&runs, &labels, &depth, 1, 5250.0, 5750.0, &camera}; }
};

TEST(LayerShape, PassingColumnsUnitsAndSpan) {
  const Layer l;
  const LayerView view = l.view();
  const LayerShape shape(view, l.params);
  for (int c = 0; c < 40; ++c) {
    EXPECT_EQ(shape.passes(c), (c >= 10 && c <= 14) || (c >= 30 && c <= 32)) << "column " << c;
  }
  EXPECT_DOUBLE_EQ(shape.columns_cm(7), 7.0);
  EXPECT_EQ(shape.columns_px(60.0), 60);
  const LayerObject o = shape.span(10, 14);
  EXPECT_EQ(o.top, 20);
  EXPECT_EQ(o.bottom, 79);
  EXPECT_EQ(o.tallest, 60);
  EXPECT_EQ(o.highest, 12);  // middle of the five columns reaching the top
  EXPECT_EQ(o.fit_first, 10);
  EXPECT_EQ(o.fit_last, 14);
  EXPECT_EQ(shape.column_depth_mm(24), 5750.0);
  EXPECT_EQ(shape.column_depth_mm(0), 0.0);
}

// Pixels that are not square (a frame stretched to another size): widths convert with fx, heights with fy.
// The band above a narrow person's head (clear_above) is rows, so it is measured with fy: with fy twice fx a
// 10 cm band is 20 rows, and another layer in the upper 10 of them is half the band (clear); counted with
// fx it would be the 10 empty rows below them alone.
TEST(LayerShape, RowsUseFyAndColumnsFx) {
  Layer l;
  for (int c = 10; c <= 14; ++c) l.fill(c, 0, 9, 4000, 2);  // another layer 11-20 rows above the body's top
  l.params.narrow.clear_above_cm = 10.0;
  const LayerObject square_o = LayerShape(l.view(), l.params).span(10, 14);
  ASSERT_EQ(square_o.top, 20);
  EXPECT_FALSE(clear_above(LayerShape(l.view(), l.params), square_o));  // 10 rows: rows 10..19, empty
  l.camera.fy_px = 1050.0;  // the body's 60 rows are 30 cm now
  l.params.near_height_cm = 20.0;
  const LayerView view = l.view();
  const LayerShape shape(view, l.params);
  EXPECT_EQ(shape.columns_px(10.0), 10);
  EXPECT_EQ(shape.rows_px(10.0), 20);
  EXPECT_DOUBLE_EQ(shape.columns_cm(7), 7.0);
  EXPECT_TRUE(clear_above(shape, shape.span(10, 14)));  // 20 rows: rows 0..19, half of them another layer
}

TEST(ObjectFit, ReachesOverTheArmAndRaisesTheTop) {
  const Layer l;
  const LayerView view = l.view();
  const LayerShape shape(view, l.params);
  LayerObject o = shape.span(10, 14);
  fit_object(shape, o, 0, 39);
  EXPECT_EQ(o.fit_first, 10);  // nothing to the left
  EXPECT_EQ(o.fit_last, 19);   // the arm; column 24 steps 500 mm deeper
  EXPECT_EQ(o.fit_top, 10);    // column 17's highest band row (band from row 0, every other row)
  EXPECT_EQ(o.first, 10);
  EXPECT_EQ(o.last, 14);
}

TEST(ObjectFit, StopsAtTheLimitsAndWithoutReach) {
  Layer l;
  const LayerView view = l.view();
  {
    const LayerShape shape(view, l.params);
    LayerObject o = shape.span(10, 14);
    fit_object(shape, o, 10, 16);  // lo..hi end at column 16
    EXPECT_EQ(o.fit_last, 16);
    EXPECT_EQ(o.fit_top, 20);  // column 17 not reached
  }
  {
    l.fill(24, 30, 40, 5300);  // now within fit.depth_step_mm, after 4 empty columns (20..23)
    l.params.column_gap = 3;
    const LayerShape shape(view, l.params);
    LayerObject o = shape.span(10, 14);
    fit_object(shape, o, 0, 39);
    EXPECT_EQ(o.fit_last, 19);
    l.params.column_gap = 4;
    const LayerShape wider(view, l.params);
    LayerObject p = wider.span(10, 14);
    fit_object(wider, p, 0, 39);
    EXPECT_EQ(p.fit_last, 24);
  }
  {
    l.params.fit.reach_cm = 0.0;
    const LayerShape shape(view, l.params);
    LayerObject o = shape.span(10, 14);
    fit_object(shape, o, 0, 39);
    EXPECT_EQ(o.fit_last, 14);
    EXPECT_EQ(o.fit_top, 20);
  }
}

TEST(ObjectFit, NearerInBandCountsNearerLayersEveryOtherRow) {
  Layer l;
  l.fill(25, 0, 9, 3000, 0);
  for (int y = 0; y < 10; ++y) l.labels(y, 25) = static_cast<std::uint8_t>(y < 5 ? 0 : 1);
  // Layer 3 sees layers 1 and 2 as nearer.
  LayerView view = l.view();
  view.label = 3;
  EXPECT_TRUE(nearer_in_band(view, 25, 0, 9, 2));   // rows 6, 8
  EXPECT_FALSE(nearer_in_band(view, 25, 0, 9, 3));
  EXPECT_TRUE(nearer_in_band(view, 25, 1, 5, 1));   // rows 1, 3, 5: row 5
  EXPECT_FALSE(nearer_in_band(view, 25, 0, 4, 1));  // rows 0, 2, 4: none
}

// Head parameters for the tests below: heads 2..6 cm wide, 8 cm above their shoulders, pieces of 5 cm.
void head_params(CandidateParams& params) {
  params.split_head.width_cm = 6.0;
  params.split_head.min_width_cm = 2.0;
  params.split_head.drop_cm = 8.0;
  params.min_part_width_cm = 5.0;
}

// A profile of 30 columns: shoulders of 80 cm (columns 3..24) with a head of 100 at 5..8 and one of 95 at
// 18..21; the object's fitted extent starts at column 5.
TEST(ObjectHeads, TwoHeadsOnAProfileAndNoneWithoutTheDrop) {
  Layer l;
  head_params(l.params);
  const LayerView view = l.view();
  const LayerShape shape(view, l.params);
  std::vector<double> h(30, 0.0);
  for (int i = 3; i <= 24; ++i) h[static_cast<std::size_t>(i)] = 80.0;
  for (int i = 5; i <= 8; ++i) h[static_cast<std::size_t>(i)] = 100.0;
  for (int i = 18; i <= 21; ++i) h[static_cast<std::size_t>(i)] = 95.0;
  LayerObject o;
  o.fit_first = 5;
  o.fit_last = 34;
  EXPECT_EQ(head_columns(shape, o, h), (std::vector<int>{5 + 6, 5 + 19}));  // the middles (5+8)/2, (18+21)/2
  for (double& v : h) v = v == 80.0 ? 93.0 : v;  // shoulders within 8 cm of both heads
  EXPECT_TRUE(head_columns(shape, o, h).empty());
  EXPECT_EQ(middle_of(0, 9, [](int c) { return c == 2 || c == 5; }), 4);
}

// A body (columns 10..30, rows 30..79) with heads at columns 12..15 (from row 20: 60 cm) and 24..27 (from
// row 22: 58 cm) over 50 cm shoulders: cut at the middle of the shoulders between them, 16..23.
TEST(ObjectHeads, CutBetweenTwoHeads) {
  Layer l;
  head_params(l.params);
  l.labels.setTo(0);
  for (ColumnRun& r : l.runs) r = ColumnRun{};
  for (int c = 10; c <= 30; ++c) l.fill(c, c >= 12 && c <= 15 ? 20 : c >= 24 && c <= 27 ? 22 : 30, 79, 5250);
  const LayerView view = l.view();
  const LayerShape shape(view, l.params);
  LayerObject o = shape.span(10, 30);
  EXPECT_DOUBLE_EQ(top_profile_cm(shape, o, 12), 60.0);
  EXPECT_DOUBLE_EQ(top_profile_cm(shape, o, 20), 50.0);
  EXPECT_DOUBLE_EQ(top_profile_cm(shape, o, 5), 0.0);
  EXPECT_EQ(cut_between_heads(shape, o, 5), 20);
  // Pieces of 12 columns cannot be cut from 21.
  EXPECT_EQ(cut_between_heads(shape, o, 12), -1);
}

// A body of columns 10..30 (rows 30..79): cut where its depth jumps (5,250 -> 5,600 mm at column 20), or,
// at one depth, at the valley of columns 19..21 (20 cm high between 50 cm shoulders).
TEST(ObjectCut, DepthJumpThenValley) {
  Layer l;
  l.labels.setTo(0);
  for (ColumnRun& r : l.runs) r = ColumnRun{};
  l.params.split.depth_jump_mm = 200.0;
  l.params.split.valley_cm = 20.0;
  l.params.split.step_cm = 0.0;
  for (int c = 10; c <= 30; ++c) l.fill(c, 30, 79, c < 20 ? 5250 : 5600);
  const LayerView view = l.view();
  {
    const LayerShape shape(view, l.params);
    const LayerObject o = shape.span(10, 30);
    EXPECT_EQ(cut_wide(shape, o, 5), 20);
    EXPECT_EQ(cut_wide(shape, o, 11), -1);  // 21 columns: no two pieces of 11
  }
  for (int c = 10; c <= 30; ++c) l.fill(c, c >= 19 && c <= 21 ? 60 : 30, 79, 5250);
  const LayerShape shape(view, l.params);
  const LayerObject o = shape.span(10, 30);
  EXPECT_DOUBLE_EQ(profile_cm(shape, o, 19), 20.0);
  EXPECT_DOUBLE_EQ(profile_cm(shape, o, 10), 50.0);
  EXPECT_EQ(cut_wide(shape, o, 5), 20);  // the middle of 19..21
  l.params.split.valley_cm = 31.0;       // deeper than the valley's 30 cm
  const LayerShape shallow(view, l.params);
  EXPECT_EQ(cut_wide(shallow, o, 5), -1);
}

}  // namespace
}  // namespace rdsf
