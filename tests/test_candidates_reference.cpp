// The candidate steps sped up for issue 17 against their straightforward versions
// (tests/support/reference_candidates.hpp): column_runs() with its row-by-row pass, floor_trimmed_bottom()
// with its histogram median, cut_crops() and the fitted extents of layer_objects(), on random label maps,
// depths and windows (runs of every length, many layers, labels outside the layer's depth range, windows
// leaving the image) and on synthetic and real frames (these skipped without ../shared/realdata).
#include <gtest/gtest.h>

#include <random>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/candidates/floor_trim.hpp"
#include "rdsf/candidates/layer_objects.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/segmentation/depth_layers.hpp"
#include "rdsf/synth/synth_sequence.hpp"
#include "support/reference_candidates.hpp"
#include "support/test_support.hpp"

namespace rdsf {
namespace {

void expect_same_runs(const cv::Mat1b& labels, int layers, int k, const std::vector<int>& occlusion,
                      const std::string& what, const std::vector<int>& holes = {}) {
  const auto fast = column_runs(labels, layers, k, occlusion, holes);
  const auto reference = test::column_runs_reference(labels, layers, k, occlusion, holes);
  ASSERT_EQ(fast.size(), reference.size());
  for (std::size_t l = 0; l < fast.size(); ++l) {
    for (std::size_t c = 0; c < fast[l].size(); ++c) {
      ASSERT_EQ(fast[l][c].top, reference[l][c].top) << what << " layer " << l << " column " << c;
      ASSERT_EQ(fast[l][c].bottom, reference[l][c].bottom) << what << " layer " << l << " column " << c;
    }
  }
}

// A label map of runs of 1..20 rows per column, labels 0..layers + 1 (layers + 1: a label beyond them).
cv::Mat1b random_label_map(std::mt19937& rng, int rows, int cols, int layers) {
  cv::Mat1b labels(rows, cols);
  for (int c = 0; c < cols; ++c) {
    int r = 0;
    while (r < rows) {
      const int length = 1 + static_cast<int>(rng() % 20);
      const auto label = static_cast<std::uint8_t>(rng() % static_cast<unsigned>(layers + 2));
      for (int i = 0; i < length && r < rows; ++i, ++r) labels(r, c) = label;
    }
  }
  return labels;
}

TEST(CandidatesReference, ColumnRunsSameOnRandomLabelMaps) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 150; ++trial) {
    const int rows = 1 + static_cast<int>(rng() % 70), cols = 1 + static_cast<int>(rng() % 9);
    const int layers = 1 + static_cast<int>(rng() % 5);
    const cv::Mat1b labels = random_label_map(rng, rows, cols, layers);
    std::vector<int> occlusion(static_cast<std::size_t>(layers) + 1), holes(occlusion.size());
    for (int& o : occlusion) o = static_cast<int>(rng() % 12);
    for (int& h : holes) h = static_cast<int>(rng() % 30);
    expect_same_runs(labels, layers, static_cast<int>(rng() % 8), trial % 2 ? occlusion : std::vector<int>{},
                     "trial " + std::to_string(trial), trial % 3 ? holes : std::vector<int>{});
  }
}

// Wide maps (the 16- and 8-column comparisons, 64-column blocks and their ends) and many layers (label bit
// sets of one, two and four words), the label 255 included.
TEST(CandidatesReference, ColumnRunsSameOnWideMapsWithManyLayers) {
  std::mt19937 rng(13);
  for (int trial = 0; trial < 60; ++trial) {
    const int rows = 1 + static_cast<int>(rng() % 90), cols = 1 + static_cast<int>(rng() % 200);
    const int layers = trial % 3 == 0 ? 1 + static_cast<int>(rng() % 254) : 1 + static_cast<int>(rng() % 12);
    cv::Mat1b labels = random_label_map(rng, rows, cols, layers);
    if (trial % 7 == 0) labels.setTo(255, labels == static_cast<std::uint8_t>(layers));
    std::vector<int> occlusion(static_cast<std::size_t>(layers) + 1);
    for (int& o : occlusion) o = static_cast<int>(rng() % 12);
    std::vector<int> holes(occlusion.size());
    for (int& h : holes) h = static_cast<int>(rng() % 30);
    expect_same_runs(labels, layers, static_cast<int>(rng() % 8), occlusion, "wide trial " + std::to_string(trial),
                     trial % 2 ? holes : std::vector<int>{});
  }
}

// floor_trimmed_bottom() against the reference on `depth`/`labels` for a random object: columns passing
// but one in `fail_one_in`, random first..last and top..bottom, the layer's range lo..lo + span - 1, a
// tolerance of 0..tolerance_steps - 1 steps of tolerance_step mm (drawn in this order).
void expect_same_trim(std::mt19937& rng, const cv::Mat1w& depth, const cv::Mat1b& labels, int layer, int lo, int span,
                      int fail_one_in, int tolerance_steps, double tolerance_step, int trial) {
  const int rows = depth.rows, cols = depth.cols;
  std::vector<char> passing(static_cast<std::size_t>(cols));
  for (char& p : passing) p = static_cast<char>(rng() % static_cast<unsigned>(fail_one_in) != 0);
  const int first = static_cast<int>(rng() % cols), last = first + static_cast<int>(rng() % (cols - first));
  const int top = static_cast<int>(rng() % rows), bottom = top + static_cast<int>(rng() % (rows - top));
  const double tolerance = static_cast<double>(rng() % static_cast<unsigned>(tolerance_steps)) * tolerance_step;
  const int fast = floor_trimmed_bottom(depth, labels, layer, first, last, top, bottom, tolerance, passing,
                                        static_cast<std::uint16_t>(lo), static_cast<std::uint16_t>(lo + span - 1));
  const int reference = test::trim_floor_reference(depth, labels, layer, first, last, top, bottom, tolerance,
                                                   [&](int c) { return passing[static_cast<std::size_t>(c)] != 0; });
  EXPECT_EQ(fast, reference) << "trial " << trial;
}

TEST(CandidatesReference, FloorTrimSameOnRandomObjects) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 300; ++trial) {
    const int rows = 2 + static_cast<int>(rng() % 60), cols = 1 + static_cast<int>(rng() % 40);
    cv::Mat1b labels(rows, cols);
    cv::Mat1w depth(rows, cols);
    const int lo = 500 + static_cast<int>(rng() % 3000), span = 1 + static_cast<int>(rng() % 400);
    for (int y = 0; y < rows; ++y) {
      for (int x = 0; x < cols; ++x) {
        labels(y, x) = static_cast<std::uint8_t>(rng() % 3);  // layer 1 is the object's
        // Mostly within the layer's range lo..lo+span-1; now and then outside it (the nth_element path).
        const bool outside = trial % 5 == 0 && rng() % 50 == 0;
        depth(y, x) = static_cast<std::uint16_t>(outside ? rng() % 8000 : lo + static_cast<int>(rng() % span));
      }
    }
    expect_same_trim(rng, depth, labels, 1, lo, span, 4, 300, 1.0, trial);
  }
}

// Wide objects with long runs of passing columns (the 8-pixel counting of floor_trim.cpp and its tails),
// layer ranges up to 3 m wide, depths now and then outside the range, and layers that are not labels.
TEST(CandidatesReference, FloorTrimSameOnWideObjects) {
  std::mt19937 rng(31);
  for (int trial = 0; trial < 200; ++trial) {
    const int rows = 2 + static_cast<int>(rng() % 120), cols = 1 + static_cast<int>(rng() % 300);
    cv::Mat1b labels(rows, cols);
    cv::Mat1w depth(rows, cols);
    // Every 23rd trial the whole 16-bit range (its counter indices do not fit 16 bits: the collecting path).
    const bool whole_range = trial % 23 == 0;
    const int lo = whole_range ? 0 : static_cast<int>(rng() % 6000);
    const int span = whole_range ? 65536 : 1 + static_cast<int>(rng() % 3000);
    const int layer = trial % 17 == 0 ? 300 : 1 + static_cast<int>(rng() % 4);
    for (int y = 0; y < rows; ++y) {
      for (int x = 0; x < cols; ++x) {
        labels(y, x) = static_cast<std::uint8_t>(rng() % 5 == 0 ? rng() % 6 : 1 + (x / 37 + y / 29) % 4);
        const bool outside = trial % 4 == 0 && rng() % 200 == 0;
        const bool floor = trial % 2 == 0 && 5 * y > 4 * rows;  // the lowest fifth nearer: floor to trim
        depth(y, x) = static_cast<std::uint16_t>(outside ? rng() % 65536
                                                 : lo + static_cast<int>(rng() % (floor ? span / 8 + 1 : span)));
      }
    }
    expect_same_trim(rng, depth, labels, layer, lo, span, 16, 3000, 1.0 / 7.0, trial);
  }
}

TEST(CandidatesReference, SameOnSyntheticFrames) {
  const synth::SynthParams p = synth::people_scene(8, 1, 4, 21);
  synth::SynthSequence sequence(p);
  for (int i = 0; i < 8; ++i) {
    const cv::Mat1w depth = sequence.frame(i).depth_mm;
    const Segmentation s = segment_depth(depth, {});
    const int layers = static_cast<int>(s.layers.size());
    expect_same_runs(s.labels, layers, 6, std::vector<int>(static_cast<std::size_t>(layers) + 1, 40),
                     "frame " + std::to_string(i), std::vector<int>(static_cast<std::size_t>(layers) + 1, i % 2 ? 30 : 0));
    std::vector<char> passing(static_cast<std::size_t>(depth.cols), 1);
    for (const DepthLayer& layer : s.layers) {
      const int fast = floor_trimmed_bottom(depth, s.labels, layer.label, 100, 400, 50, 470, 150.0, passing,
                                            layer.min_depth_mm, layer.max_depth_mm);
      EXPECT_EQ(fast, test::trim_floor_reference(depth, s.labels, layer.label, 100, 400, 50, 470, 150.0,
                                                 [](int) { return true; }));
    }
  }
}

void expect_same_crops(const Candidate& fast, const Candidate& reference, const std::string& what) {
  ASSERT_EQ(fast.depth_crop.size(), reference.depth_crop.size()) << what;
  EXPECT_EQ(cv::countNonZero(fast.depth_crop != reference.depth_crop), 0) << what;
  ASSERT_EQ(fast.colour_crop.empty(), reference.colour_crop.empty()) << what;
  if (!fast.colour_crop.empty()) {
    cv::Mat differ;
    cv::absdiff(fast.colour_crop, reference.colour_crop, differ);
    EXPECT_EQ(cv::countNonZero(differ.reshape(1)), 0) << what;
  }
}

TEST(CandidatesReference, CutCropsSameOnRandomWindows) {
  std::mt19937 rng(14);
  DepthFrame frame;
  frame.depth_mm.create(60, 80);
  frame.bgr.create(60, 80);
  cv::randu(frame.depth_mm, 0, 5000);
  cv::randu(frame.bgr, 0, 256);
  cv::Mat1b labels(60, 80);
  cv::randu(labels, 0, 4);
  for (int trial = 0; trial < 400; ++trial) {
    // Windows inside, across an edge, beyond the image, narrower and wider than the crop.
    const cv::Rect window(static_cast<int>(rng() % 140) - 40, static_cast<int>(rng() % 110) - 30,
                          1 + static_cast<int>(rng() % 120), 1 + static_cast<int>(rng() % 100));
    const cv::Size crop(1 + static_cast<int>(rng() % 70), 1 + static_cast<int>(rng() % 130));
    DepthFrame shown = frame;
    if (trial % 3 == 0) shown.bgr.release();
    Candidate fast, reference;
    cut_crops(shown, labels, 1 + trial % 3, window, crop, fast);
    test::cut_crops_reference(shown, labels, 1 + trial % 3, window, crop, reference);
    expect_same_crops(fast, reference, "trial " + std::to_string(trial));
  }
}

// Synthetic frames with colour (8, 1..4 people) and the real frames of ../shared/realdata when present.
std::vector<DepthFrame> candidate_frames() {
  synth::SynthParams p = synth::people_scene(16, 1, 4, 23);
  p.rgb = true;
  std::vector<DepthFrame> frames = test::synthetic_frames(p);
  if (!test::realdata_dir().empty()) {
    for (const char* group : {"people", "empty"}) {
      auto source = open_frame_source((test::realdata_dir() / group).string());
      DepthFrame frame;
      while (source->next(frame)) {
        frames.push_back(frame);
        frame = DepthFrame{};  // the source may reuse the frame's buffers
      }
    }
  }
  return frames;
}

// Every object's fitted extent (objects neither joined nor split, so each is one passing span fitted over
// the whole width) equals the column-by-column walk, and every candidate's crops the pixel-by-pixel cut.
// Every object of layer_objects(view, params) has the fitted extent of the column-by-column walk; counts
// the objects and those whose fitted extent reaches beyond their passing columns.
void expect_same_fitted_extents(const LayerView& view, const CandidateParams& params, int& objects, int& widened) {
  const LayerObjects found = layer_objects(view, params);
  const int reach = static_cast<int>(params.fit.reach_cm * 10.0 * view.camera->fx_px / std::max(1.0, view.depth_mm_mean));
  for (const LayerObject& o : found.objects) {
    const test::FittedExtent reference = test::fitted_extent_reference(
        *view.labels, *view.depth_mm, view.label, found.passing, o.first, o.last, o.top, o.bottom, reach,
        params.column_gap, params.fit.depth_step_mm, 0, view.labels->cols - 1);
    EXPECT_EQ(o.fit_first, reference.first) << "layer " << view.label << " object at column " << o.first;
    EXPECT_EQ(o.fit_last, reference.last) << "layer " << view.label << " object at column " << o.first;
    EXPECT_EQ(o.fit_top, reference.top) << "layer " << view.label << " object at column " << o.first;
    ++objects;
    widened += reference.last - reference.first > o.last - o.first;
  }
}

// The passing columns of layer_objects() (a bisected shortest passing length per layer) against the
// height test of every column, at random depths (none and negative ones too) and thresholds.
TEST(CandidatesReference, PassingColumnsSameAsTheHeightTest) {
  std::mt19937 rng(43);
  const CameraModel camera;
  const cv::Mat1b labels(480, 200, std::uint8_t{1});
  const cv::Mat1w depth(480, 200, std::uint16_t{3000});
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<ColumnRun> runs(200);
    for (ColumnRun& r : runs) {
      if (rng() % 5 == 0) continue;  // no run
      r.top = static_cast<int>(rng() % 480);
      r.bottom = r.top + static_cast<int>(rng() % static_cast<unsigned>(480 - r.top));
    }
    CandidateParams params;
    params.height_at_column_depth = false;
    params.border.height_cm = 0;  // the height test alone (the border rule: CandidateFinder.PeopleTheImageCuts*)
    params.near_height_cm = params.far_height_cm = static_cast<double>(rng() % 200);
    const double mean = trial % 10 == 0 ? -static_cast<double>(rng() % 100) : static_cast<double>(rng() % 9000);
    const LayerView view{&runs, &labels, &depth, 1, mean, mean + 200.0, &camera};
    const LayerObjects found = layer_objects(view, params);
    const double min_height_cm = params.threshold_height_cm(mean);
    for (int c = 0; c < 200; ++c) {
      const bool passes = camera.height_cm(runs[static_cast<std::size_t>(c)].length(), mean) >= min_height_cm;
      EXPECT_EQ(found.passing[static_cast<std::size_t>(c)] != 0, passes) << "trial " << trial << " column " << c;
    }
  }
}

// Random maps of upright blocks (label 1) with pieces beside them at other depths, before a background
// (label 2) with holes (0): images narrower than 16 columns, objects at the borders, column gaps that make
// the first gather wider than 16 columns (the one-by-one gather) and every depth step.
TEST(CandidatesReference, FittedExtentsSameOnRandomMaps) {
  std::mt19937 rng(41);
  const CameraModel camera;
  int objects = 0, widened = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int rows = 200 + static_cast<int>(rng() % 200), cols = 4 + static_cast<int>(rng() % 160);
    cv::Mat1b labels(rows, cols, std::uint8_t{2});
    cv::Mat1w depth(rows, cols);
    for (int y = 0; y < rows; ++y) {
      for (int x = 0; x < cols; ++x) depth(y, x) = static_cast<std::uint16_t>(5000 + rng() % 500);
    }
    const auto fill = [&](int x0, int y0, int w, int h, std::uint8_t label, int mm, int noise) {
      for (int y = std::max(0, y0); y < std::min(rows, y0 + h); ++y) {
        for (int x = std::max(0, x0); x < std::min(cols, x0 + w); ++x) {
          labels(y, x) = label;
          depth(y, x) = static_cast<std::uint16_t>(mm + static_cast<int>(rng() % static_cast<unsigned>(noise + 1)));
        }
      }
    };
    const int blocks = 1 + static_cast<int>(rng() % 4);
    for (int b = 0; b < blocks; ++b) {
      const int x = static_cast<int>(rng() % cols), w = 1 + static_cast<int>(rng() % 30), top = static_cast<int>(rng() % (rows / 3));
      const int mm = 2500 + static_cast<int>(rng() % 1000);
      fill(x, top, w, rows - top - static_cast<int>(rng() % 20), 1, mm, 60);
      for (int piece = static_cast<int>(rng() % 5); piece > 0; --piece) {  // arms, hands, furniture beside it
        const int px = x + (rng() % 2 == 0 ? -1 : 1) * static_cast<int>(rng() % 40), py = top + static_cast<int>(rng() % rows) - rows / 4;
        fill(px, py, 1 + static_cast<int>(rng() % 12), 2 + static_cast<int>(rng() % 60), 1, mm - 300 + static_cast<int>(rng() % 600), 80);
      }
    }
    for (int holes = static_cast<int>(rng() % 400); holes > 0; --holes) {
      labels(static_cast<int>(rng() % rows), static_cast<int>(rng() % cols)) = 0;
    }
    CandidateParams params;
    params.join.pieces = false;
    params.split_head.drop_cm = 0;
    params.column_gap = static_cast<int>(rng() % 21);
    params.fit.reach_cm = 10.0 + static_cast<double>(rng() % 80);
    params.fit.depth_step_mm = static_cast<double>(rng() % 3) * 150.0;
    const auto runs = column_runs(labels, 2, params.k);
    const LayerView view{&runs[1], &labels, &depth, 1, 3000.0, 3500.0, &camera};
    expect_same_fitted_extents(view, params, objects, widened);
  }
  EXPECT_GT(objects, 100);
  EXPECT_GT(widened, 50);
}

TEST(CandidatesReference, FittedExtentsAndCropsSameOnFrames) {
  CandidateParams params;
  params.join.pieces = false;
  params.split_head.drop_cm = 0;
  int objects = 0, widened = 0, candidates = 0;
  for (const DepthFrame& frame : candidate_frames()) {
    const Segmentation s = segment_depth(frame.depth_mm, {});
    const auto runs = column_runs(s.labels, static_cast<int>(s.layers.size()), params.k);
    for (const DepthLayer& layer : s.layers) {
      const LayerView view{&runs[static_cast<std::size_t>(layer.label)], &s.labels, &frame.depth_mm, layer.label,
                           layer.mean_depth_mm, static_cast<double>(layer.max_depth_mm), &frame.camera};
      expect_same_fitted_extents(view, params, objects, widened);
    }
    for (const Candidate& c : find_candidates(frame, s, {})) {
      Candidate reference;
      test::cut_crops_reference(frame, s.labels, c.layer, c.window_unclipped, c.depth_crop.size(), reference);
      expect_same_crops(c, reference, "candidate at " + std::to_string(c.window.x) + "," + std::to_string(c.window.y));
      ++candidates;
    }
  }
  EXPECT_GT(objects, 10);
  EXPECT_GT(widened, 3);  // some fitted extents reach beyond the passing columns
  EXPECT_GT(candidates, 5);
}

}  // namespace
}  // namespace rdsf
