// The joining (object_join.hpp), narrow-person (narrow_person.hpp), keeping (object_keep.hpp) and splitting
// (object_split.hpp) steps of layer_objects() one by one, and layer_objects() as their composition, on
// hand-built layers at 5,250 mm, where with fx = fy = 525 one pixel is one centimetre both ways.
#include <gtest/gtest.h>

#include <vector>

#include "rdsf/candidates/layer_objects.hpp"
#include "rdsf/candidates/narrow_person.hpp"
#include "rdsf/candidates/object_join.hpp"
#include "rdsf/candidates/object_keep.hpp"
#include "rdsf/candidates/object_split.hpp"

namespace rdsf {
namespace {

// A layer 1 at 5,250 mm on a rows x cols label map (0: no reading). A column passes threshold_height when
// its run of layer 1 is at least 50 rows (50 cm: relaxed mode, near_height_cm = 50).
struct HandLayer {
  cv::Mat1b labels;
  cv::Mat1w depth;
  std::vector<ColumnRun> runs;
  CameraModel camera;
  CandidateParams params;
  HandLayer(int rows, int cols)
      : labels(cv::Mat1b::zeros(rows, cols)), depth(cv::Mat1w::zeros(rows, cols)), runs(static_cast<std::size_t>(cols)) {
    params.mode = HeightMode::relaxed;
    params.near_height_cm = 50.0;
    params.height_at_column_depth = false;
  }
  // Columns first..last, rows top..bottom of `label` at depth_mm; for layer 1 they become the columns' runs.
  void block(int first, int last, int top, int bottom, int depth_mm = 5250, int label = 1) {
    labels(cv::Range(top, bottom + 1), cv::Range(first, last + 1)).setTo(label);
    depth(cv::Range(top, bottom + 1), cv::Range(first, last + 1)).setTo(depth_mm);
    for (int c = first; c <= last && label == 1; ++c) runs[static_cast<std::size_t>(c)] = {top, bottom};
  }
  LayerView view() const { return {&runs, &labels, &depth, 1, 5250.0, 5750.0, &camera}; }
};

// first..last of each object.
std::vector<std::pair<int, int>> extents(const std::vector<LayerObject>& objects) {
  std::vector<std::pair<int, int>> found;
  for (const LayerObject& o : objects) found.emplace_back(o.first, o.last);
  return found;
}

using Extents = std::vector<std::pair<int, int>>;

TEST(ObjectJoin, ColumnsOfAnEmptyLayerAndOfAOneColumnImage) {
  const HandLayer empty(100, 40);
  const LayerView view = empty.view();
  EXPECT_TRUE(join_columns(LayerShape(view, empty.params)).empty());

  HandLayer one(100, 1);
  one.block(0, 0, 20, 79);
  const LayerView one_view = one.view();
  const std::vector<LayerObject> found = join_columns(LayerShape(one_view, one.params));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].first, 0);
  EXPECT_EQ(found[0].last, 0);
  EXPECT_EQ(found[0].top, 20);
  EXPECT_EQ(found[0].bottom, 79);
}

// Passing columns 5..9, 13..15 (a gap of 3: 10..12, column 11 too short to pass) and 20..22 (a gap of 4).
TEST(ObjectJoin, ColumnsJoinAcrossAGapOfExactlyColumnGap) {
  HandLayer l(100, 30);
  l.block(5, 9, 20, 79);
  l.block(11, 11, 60, 79);
  l.block(13, 15, 25, 79);
  l.block(20, 22, 20, 79);
  const LayerView view = l.view();
  l.params.column_gap = 3;
  const std::vector<LayerObject> found = join_columns(LayerShape(view, l.params));
  EXPECT_EQ(extents(found), (Extents{{5, 15}, {20, 22}}));
  EXPECT_EQ(found[0].fit_first, 5);  // a span: not yet fitted
  EXPECT_EQ(found[0].fit_last, 15);
  l.params.column_gap = 2;
  EXPECT_EQ(extents(join_columns(LayerShape(view, l.params))), (Extents{{5, 9}, {13, 15}, {20, 22}}));
  l.params.column_gap = 4;
  EXPECT_EQ(extents(join_columns(LayerShape(view, l.params))), (Extents{{5, 22}}));
}

// Three pieces whose fitted extents touch (10..34, 35..62, 63..74): one object while no wider than a person.
TEST(ObjectJoin, PiecesWhoseFittedExtentsTouchJoinUpToAPersonsWidth) {
  HandLayer l(100, 80);
  l.block(10, 29, 20, 79);
  l.block(40, 59, 25, 79);
  l.block(65, 74, 30, 79);
  const LayerView view = l.view();
  const LayerShape shape(view, l.params);
  LayerObject a = shape.span(10, 29), b = shape.span(40, 59), c = shape.span(65, 74);
  a.fit_last = 34, a.fit_top = 15;
  b.fit_first = 35, b.fit_last = 62, b.fit_top = 18;
  c.fit_first = 63;
  const std::vector<LayerObject> joined = join_pieces(shape, {a, b, c});
  ASSERT_EQ(joined.size(), 1u);
  const LayerObject& o = joined[0];
  EXPECT_EQ(o.first, 10);
  EXPECT_EQ(o.last, 74);
  EXPECT_EQ(o.fit_first, 10);
  EXPECT_EQ(o.fit_last, 74);
  EXPECT_EQ(o.top, 20);
  EXPECT_EQ(o.fit_top, 15);
  EXPECT_EQ(o.bottom, 79);
  EXPECT_EQ(o.tallest, 60);

  // Together 65 cm: wider than a person of 64 cm, only the first two (53 cm) join.
  CandidateParams p = l.params;
  p.max_person_width_cm = 64.0;
  const LayerShape narrower(view, p);
  const std::vector<LayerObject> two = join_pieces(narrower, {a, b, c});
  EXPECT_EQ(extents(two), (Extents{{10, 59}, {65, 74}}));
  EXPECT_EQ(two[1].fit_first, 63);  // unchanged
  // One column between the fitted extents: nothing joins.
  b.fit_first = 36;
  c.fit_first = 64;
  EXPECT_EQ(extents(join_pieces(shape, {a, b, c})), (Extents{{10, 29}, {40, 59}, {65, 74}}));
  EXPECT_TRUE(join_pieces(shape, {}).empty());
}

// Two pieces of 3 cm (columns 10..12, 16..18, fitted extents touching at 14 | 15), each narrower than
// min_width_cm: they join only in a layer nearer than join.narrow_layers_below_mm, and with
// join.narrow_passing only when their 6 passing columns reach narrow.passing_width_cm.
TEST(ObjectJoin, NarrowPiecesJoinOnlyNearAndWithEnoughPassingColumns) {
  HandLayer l(100, 40);
  l.block(10, 12, 20, 79);
  l.block(16, 18, 20, 79);
  l.block(19, 30, 20, 79);  // makes the second piece wide when it is 16..30
  const LayerView view = l.view();
  const auto joined = [&](const CandidateParams& params, int second_last) {
    const LayerShape shape(view, params);
    LayerObject a = shape.span(10, 12), b = shape.span(16, second_last);
    a.fit_last = 14;
    b.fit_first = 15;
    return join_pieces(shape, {a, b}).size() == 1;
  };
  CandidateParams p = l.params;
  ASSERT_EQ(p.join.narrow_layers_below_mm, 3500.0);  // the default: 5,250 mm is too far
  EXPECT_FALSE(joined(p, 18));
  EXPECT_TRUE(joined(p, 30));  // one of them wide: depth and passing columns do not matter
  p.join.narrow_layers_below_mm = 5251.0;
  EXPECT_TRUE(joined(p, 18));
  p.narrow.passing_width_cm = 6.0;  // exactly the 6 passing columns
  EXPECT_TRUE(joined(p, 18));
  p.narrow.passing_width_cm = 7.0;
  EXPECT_FALSE(joined(p, 18));
  p.join.narrow_passing = false;
  EXPECT_TRUE(joined(p, 18));
  p.join.narrow_layers_below_mm = 5250.0;  // the layer's own depth is not nearer
  EXPECT_FALSE(joined(p, 18));
}

TEST(NarrowPerson, PassingCmLeavesTheGapsOut) {
  HandLayer l(100, 30);
  l.block(10, 11, 20, 79);
  l.block(12, 17, 60, 79);  // 20 rows: too short to pass
  l.block(18, 19, 20, 79);
  const LayerView view = l.view();
  const LayerShape shape(view, l.params);
  const LayerObject o = shape.span(10, 19);
  EXPECT_DOUBLE_EQ(passing_cm(shape, o), 4.0);
  EXPECT_DOUBLE_EQ(shape.columns_cm(o.last - o.first + 1), 10.0);
}

// An object in columns 10..13 from row `top`; the band above it is narrow.clear_above_cm = 10 rows of 4
// columns (40 pixels), of which `other` rows (the lowest ones) hold layer `label`.
bool clear_with(int top, int other_rows, int label) {
  HandLayer l(100, 20);
  l.block(10, 13, top, 99);
  l.labels(cv::Range(top - other_rows, top), cv::Range(10, 14)).setTo(label);  // not layer 1's runs
  l.params.narrow.clear_above_cm = 10.0;
  const LayerView view = l.view();
  const LayerShape shape(view, l.params);
  return clear_above(shape, shape.span(10, 13));
}

TEST(NarrowPerson, ClearAboveNeedsOtherLayersOverHalfTheBand) {
  EXPECT_FALSE(clear_with(30, 0, 2));   // missing readings above
  EXPECT_TRUE(clear_with(30, 10, 2));   // a background
  EXPECT_TRUE(clear_with(30, 5, 2));    // exactly half: 20 of 40
  EXPECT_FALSE(clear_with(30, 4, 2));   // 16 of 40
  EXPECT_TRUE(clear_with(30, 10, 3));   // a nearer or farther layer alike
  EXPECT_FALSE(clear_with(30, 10, 1));  // the object's own layer is no background
  // At the top of the image the rows above it count as missing: from row 5, its 5 rows are half the band.
  EXPECT_TRUE(clear_with(5, 5, 2));
  EXPECT_FALSE(clear_with(4, 4, 2));
  EXPECT_FALSE(clear_with(0, 0, 2));
}

// A person whose legs (columns 18..25, rows 10..99: 8 cm) alone pass, under a torso in columns 5..38 (rows
// 10..39: 30 rows, too short to pass), with a background (layer 2) in rows 0..9 above the legs. Its fitted
// extent 5..38 is 34 cm wide, its height (fitted top 10 to row 99) 90 cm; the rule on at 20 cm.
struct NarrowScene {
  HandLayer l{100, 50};
  LayerObject person;
  NarrowScene() {
    l.block(5, 38, 10, 39);
    l.block(18, 25, 10, 99);
    l.block(18, 25, 0, 9, 6000, 2);
    l.params.narrow.fitted_width_cm = 20.0;
    l.params.narrow.layers_below_mm = 6000.0;  // 5,000 by default
    const LayerView view = l.view();
    person = LayerShape(view, l.params).span(18, 25);
    person.fit_first = 5;
    person.fit_last = 38;
    person.fit_top = 10;
  }
  bool narrow(const CandidateParams& params) const {
    const LayerView view = l.view();
    return narrow_person(LayerShape(view, params), person);
  }
};

TEST(NarrowPerson, KeptOnlyWithAPersonsWidthHeightDepthAndBackground) {
  NarrowScene s;
  CandidateParams p = s.l.params;
  ASSERT_EQ(p.narrow.min_height_cm, 90.0);  // exactly its height
  EXPECT_TRUE(s.narrow(p));
  const auto without = [&](auto change) {
    CandidateParams q = p;
    change(q);
    return s.narrow(q);
  };
  EXPECT_FALSE(without([](CandidateParams& q) { q.narrow.fitted_width_cm = 0; }));     // the rule off
  EXPECT_FALSE(without([](CandidateParams& q) { q.narrow.fitted_width_cm = 35; }));    // fitted 34 cm
  EXPECT_TRUE(without([](CandidateParams& q) { q.narrow.fitted_width_cm = 34; }));
  EXPECT_FALSE(without([](CandidateParams& q) { q.narrow.passing_width_cm = 9; }));    // legs 8 cm
  EXPECT_FALSE(without([](CandidateParams& q) { q.narrow.layers_below_mm = 5250; }));  // too far
  EXPECT_FALSE(without([](CandidateParams& q) { q.narrow.min_height_cm = 91; }));      // too short
  s.l.labels(cv::Range(0, 10), cv::Range(18, 26)).setTo(0);                           // nothing above
  EXPECT_FALSE(s.narrow(p));
}

TEST(ObjectKeep, WideEnoughOrANarrowPerson) {
  NarrowScene s;
  s.l.params.narrow.fitted_width_cm = 0;  // off: 8 cm of passing columns are too narrow
  const LayerView view = s.l.view();
  EXPECT_FALSE(keep_object(LayerShape(view, s.l.params), s.person));
  s.l.params.narrow.fitted_width_cm = 20.0;
  EXPECT_TRUE(keep_object(LayerShape(view, s.l.params), s.person));
  s.l.params.min_width_cm = 8.0;  // wide enough without the rule
  s.l.params.narrow.fitted_width_cm = 0;
  EXPECT_TRUE(keep_object(LayerShape(view, s.l.params), s.person));
}

// Objects of 12 cm (fitted as wide) at the left border, inside and at the right border, and one of 50 cm.
TEST(ObjectKeep, NotAWallNorAPostUnlessAtTheBorder) {
  HandLayer l(100, 200);
  l.block(0, 11, 20, 79);
  l.block(50, 61, 20, 79);
  l.block(100, 149, 20, 79);
  l.block(188, 199, 20, 79);
  const LayerView view = l.view();
  const auto kept = [&](const CandidateParams& params) {
    const LayerShape shape(view, params);
    std::vector<bool> found;
    for (const auto& [first, last] : Extents{{0, 11}, {50, 61}, {100, 149}, {188, 199}}) {
      found.push_back(keep_object(shape, shape.span(first, last)));
    }
    return found;
  };
  CandidateParams p = l.params;
  EXPECT_EQ(kept(p), (std::vector<bool>{true, false, true, true}));  // 12 cm < min_fitted_width_cm 15 inside
  p.min_fitted_width_cm = 12.0;
  EXPECT_EQ(kept(p), (std::vector<bool>{true, true, true, true}));
  p.max_object_width_cm = 49.0;  // a wall
  EXPECT_EQ(kept(p), (std::vector<bool>{true, true, false, true}));
  p.max_object_width_cm = 50.0;
  EXPECT_EQ(kept(p), (std::vector<bool>{true, true, true, true}));
  p.max_object_width_cm = 0;  // no limit
  p.min_width_cm = 13.0;      // 12 cm is too narrow, at the border too
  EXPECT_EQ(kept(p), (std::vector<bool>{false, false, true, false}));
}

TEST(ObjectSplit, EnabledByItsParameters) {
  CandidateParams p;
  EXPECT_FALSE(split_wide_enabled(p.split));
  p.split.valley_cm = 1;
  EXPECT_TRUE(split_wide_enabled(p.split));
  p = {};
  p.split.depth_jump_mm = 1;
  EXPECT_TRUE(split_wide_enabled(p.split));
  p = {};
  p.split.step_cm = 1;
  EXPECT_TRUE(split_wide_enabled(p.split));

  const HandLayer l(100, 10);
  const LayerView view = l.view();  // at 5,250 mm
  p = l.params;
  ASSERT_GT(p.split_head.drop_cm, 0);
  EXPECT_FALSE(split_heads_enabled(LayerShape(view, p)));  // split_head.layers_below_mm 4,000 by default
  p.split_head.layers_below_mm = 5251.0;
  EXPECT_TRUE(split_heads_enabled(LayerShape(view, p)));
  p.split_head.drop_cm = 0;
  EXPECT_FALSE(split_heads_enabled(LayerShape(view, p)));
}

// Two people side by side, 40 cm each, at 5,250 mm (columns 10..49) and 5,600 mm (50..89), rows 20..99:
// wider than a person of 60 cm, the object is cut at the depth jump into two pieces.
struct TwoPeople {
  HandLayer l{120, 140};
  TwoPeople() {
    l.block(10, 49, 20, 99, 5250);
    l.block(50, 89, 20, 99, 5600);
    l.params.split.depth_jump_mm = 200.0;
    l.params.max_person_width_cm = 60.0;
    l.params.min_part_width_cm = 25.0;
  }
};

TEST(ObjectSplit, AWideObjectSplitsIntoTwoPeople) {
  TwoPeople t;
  const LayerView view = t.l.view();
  const LayerShape shape(view, t.l.params);
  LayerObject whole = shape.span(10, 89);
  whole.object = 3;
  const ObjectPieces found = object_pieces(shape, whole);
  EXPECT_FALSE(found.by_heads);
  EXPECT_EQ(extents(found.pieces), (Extents{{10, 49}, {50, 89}}));
  for (const LayerObject& piece : found.pieces) {
    EXPECT_TRUE(piece.part);
    EXPECT_EQ(piece.object, 3);
    EXPECT_EQ(piece.fit_first, piece.first);  // nothing beside them to reach over
    EXPECT_EQ(piece.fit_last, piece.last);
  }
  std::vector<LayerObject> out;
  split_object(shape, whole, out);
  EXPECT_EQ(extents(out), (Extents{{10, 49}, {50, 89}}));
  // split.keep_whole: the whole first.
  CandidateParams keep = t.l.params;
  keep.split.keep_whole = true;
  out.clear();
  split_object(LayerShape(view, keep), whole, out);
  EXPECT_EQ(extents(out), (Extents{{10, 89}, {10, 49}, {50, 89}}));
  EXPECT_FALSE(out[0].part);
  // Exactly a person's width (80 cm) is not cut: the object stays alone.
  CandidateParams wider = t.l.params;
  wider.max_person_width_cm = 80.0;
  const LayerShape person(view, wider);
  EXPECT_TRUE(object_pieces(person, whole).pieces.empty());
  out.clear();
  split_object(person, whole, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_FALSE(out[0].part);
  EXPECT_EQ(out[0].object, 3);
}

// The second person's passing columns are only 50..54 (55..89 are 40 rows high, too short): the right
// piece, 5 cm over its passing columns, is dropped, and the left one alone replaces the whole.
TEST(ObjectSplit, APieceNarrowerThanMinWidthIsDropped) {
  TwoPeople t;
  t.l.labels(cv::Range(20, 60), cv::Range(55, 90)).setTo(0);
  t.l.block(55, 89, 60, 99, 5600);
  const LayerView view = t.l.view();
  const LayerShape shape(view, t.l.params);
  LayerObject whole = shape.span(10, 54);
  whole.fit_last = 89;
  std::vector<LayerObject> out;
  split_object(shape, whole, out);
  EXPECT_EQ(extents(out), (Extents{{10, 49}}));
  EXPECT_TRUE(out[0].part);
}

// Three people (5,250 / 5,600 / 5,250 mm): the first cut at the first of the two equal jumps (50), the
// right piece, 80 cm, again at 90.
TEST(ObjectSplit, EachPieceIsCutAgain) {
  TwoPeople t;
  t.l.block(90, 129, 20, 99, 5250);
  const LayerView view = t.l.view();
  const LayerShape shape(view, t.l.params);
  const ObjectPieces found = object_pieces(shape, shape.span(10, 129));
  EXPECT_EQ(extents(found.pieces), (Extents{{10, 49}, {50, 89}, {90, 129}}));
}

// A body of columns 10..30 (rows 30..79) with heads at 12..15 (from row 20) and 24..27 (from row 22), as in
// ObjectHeads.CutBetweenTwoHeads: 21 cm wide, it is cut between the heads at column 20.
TEST(ObjectSplit, TwoHeadsCutAnObjectOfAnyWidth) {
  HandLayer l(100, 40);
  for (int c = 10; c <= 30; ++c) l.block(c, c, c >= 12 && c <= 15 ? 20 : c >= 24 && c <= 27 ? 22 : 30, 79);
  l.params.split_head.width_cm = 6.0;
  l.params.split_head.min_width_cm = 2.0;
  l.params.split_head.drop_cm = 8.0;
  l.params.min_part_width_cm = 5.0;
  l.params.split_head.layers_below_mm = 6000.0;
  const LayerView view = l.view();
  const LayerShape shape(view, l.params);
  const LayerObject whole = shape.span(10, 30);
  const ObjectPieces found = object_pieces(shape, whole);
  EXPECT_TRUE(found.by_heads);
  EXPECT_EQ(extents(found.pieces), (Extents{{10, 19}, {20, 30}}));
  std::vector<LayerObject> out;
  CandidateParams p = l.params;
  p.split.keep_whole = true;  // for cuts of wide objects only
  split_object(LayerShape(view, p), whole, out);
  EXPECT_EQ(extents(out), (Extents{{10, 19}, {20, 30}}));
  p.split_head.keep_whole = true;
  out.clear();
  split_object(LayerShape(view, p), whole, out);
  EXPECT_EQ(extents(out), (Extents{{10, 30}, {10, 19}, {20, 30}}));
}

TEST(LayerObjects, EmptyLayerAndOneColumn) {
  const HandLayer empty(100, 40);
  const LayerObjects none = layer_objects(empty.view(), empty.params);
  EXPECT_TRUE(none.objects.empty());
  EXPECT_EQ(none.passing, std::vector<char>(40, 0));

  HandLayer one(100, 1);
  one.block(0, 0, 20, 79);
  const LayerObjects narrow = layer_objects(one.view(), one.params);
  EXPECT_TRUE(narrow.objects.empty());  // 1 cm < min_width_cm
  EXPECT_EQ(narrow.passing, std::vector<char>(1, 1));
  one.params.min_width_cm = 1.0;
  const LayerObjects found = layer_objects(one.view(), one.params);
  ASSERT_EQ(found.objects.size(), 1u);  // at the border: no min_fitted_width_cm
  EXPECT_EQ(found.objects[0].first, 0);
  EXPECT_EQ(found.objects[0].fit_last, 0);
  EXPECT_EQ(found.objects[0].object, 0);
}

// One layer holding, left to right: a person whose passing columns part (10..19 and 30..39, an arm of 31
// rows between them), a wall (60..159: 100 cm), two people side by side (180..219 at 5,250 mm, 220..259 at
// 5,600 mm) and a post (280..291: 12 cm).
TEST(LayerObjects, JoinsKeepsAndSplitsInOrder) {
  HandLayer l(120, 300);
  l.block(10, 19, 20, 99);
  l.block(20, 29, 20, 50);
  l.block(30, 39, 20, 99);
  l.block(60, 159, 20, 99);
  l.block(180, 219, 20, 99, 5250);
  l.block(220, 259, 20, 99, 5600);
  l.block(280, 291, 20, 99);
  l.params.max_object_width_cm = 90.0;
  l.params.max_person_width_cm = 60.0;
  l.params.split.depth_jump_mm = 200.0;
  const LayerObjects found = layer_objects(l.view(), l.params);
  EXPECT_EQ(extents(found.objects), (Extents{{10, 39}, {180, 219}, {220, 259}}));
  ASSERT_EQ(found.objects.size(), 3u);
  EXPECT_EQ(found.objects[0].fit_first, 10);  // the joined pieces, fitted over the arm
  EXPECT_EQ(found.objects[0].fit_last, 39);
  EXPECT_EQ(found.objects[0].object, 0);
  EXPECT_FALSE(found.objects[0].part);
  for (int i : {1, 2}) {
    EXPECT_TRUE(found.objects[static_cast<std::size_t>(i)].part);
    EXPECT_EQ(found.objects[static_cast<std::size_t>(i)].object, 1);  // the wall was no object
  }
  // Without joining, the person's two pieces are objects (fitted over the arm, both 20 cm wide).
  l.params.join.pieces = false;
  EXPECT_EQ(extents(layer_objects(l.view(), l.params).objects), (Extents{{10, 19}, {30, 39}, {180, 219}, {220, 259}}));
}

}  // namespace
}  // namespace rdsf
