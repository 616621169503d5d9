// The candidate steps sped up for issue 17 against their straightforward versions
// (tests/support/reference_candidates.hpp): column_runs() with its word-at-a-time run scan, and
// floor_trimmed_bottom() with its histogram median, on random label maps and depths (runs of every length,
// labels outside the layer's depth range) and on the layers of synthetic frames.
#include <gtest/gtest.h>

#include <random>

#include "rdsf/candidates/floor_trim.hpp"
#include "rdsf/segmentation/depth_layers.hpp"
#include "rdsf/synth/synth_sequence.hpp"
#include "support/reference_candidates.hpp"

namespace rdsf {
namespace {

void expect_same_runs(const cv::Mat1b& labels, int layers, int k, const std::vector<int>& occlusion, const std::string& what) {
  const auto fast = column_runs(labels, layers, k, occlusion);
  const auto reference = test::column_runs_reference(labels, layers, k, occlusion);
  ASSERT_EQ(fast.size(), reference.size());
  for (std::size_t l = 0; l < fast.size(); ++l) {
    for (std::size_t c = 0; c < fast[l].size(); ++c) {
      ASSERT_EQ(fast[l][c].top, reference[l][c].top) << what << " layer " << l << " column " << c;
      ASSERT_EQ(fast[l][c].bottom, reference[l][c].bottom) << what << " layer " << l << " column " << c;
    }
  }
}

TEST(CandidatesReference, ColumnRunsSameOnRandomLabelMaps) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 150; ++trial) {
    const int rows = 1 + static_cast<int>(rng() % 70), cols = 1 + static_cast<int>(rng() % 9);
    const int layers = 1 + static_cast<int>(rng() % 5);
    cv::Mat1b labels(rows, cols);
    for (int c = 0; c < cols; ++c) {
      int r = 0;
      while (r < rows) {  // runs of 1..20 rows of one label
        const int length = 1 + static_cast<int>(rng() % 20);
        const auto label = static_cast<std::uint8_t>(rng() % (layers + 2));  // layers + 1: a label beyond them
        for (int i = 0; i < length && r < rows; ++i, ++r) labels(r, c) = label;
      }
    }
    std::vector<int> occlusion(static_cast<std::size_t>(layers) + 1);
    for (int& o : occlusion) o = static_cast<int>(rng() % 12);
    expect_same_runs(labels, layers, static_cast<int>(rng() % 8), trial % 2 ? occlusion : std::vector<int>{},
                     "trial " + std::to_string(trial));
  }
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
    std::vector<char> passing(static_cast<std::size_t>(cols));
    for (char& p : passing) p = static_cast<char>(rng() % 4 != 0);
    const int first = static_cast<int>(rng() % cols), last = first + static_cast<int>(rng() % (cols - first));
    const int top = static_cast<int>(rng() % rows), bottom = top + static_cast<int>(rng() % (rows - top));
    const double tolerance = static_cast<double>(rng() % 300);
    const int fast = floor_trimmed_bottom(depth, labels, 1, first, last, top, bottom, tolerance, passing,
                                          static_cast<std::uint16_t>(lo), static_cast<std::uint16_t>(lo + span - 1));
    const int reference = test::trim_floor_reference(depth, labels, 1, first, last, top, bottom, tolerance,
                                                     [&](int c) { return passing[static_cast<std::size_t>(c)] != 0; });
    EXPECT_EQ(fast, reference) << "trial " << trial;
  }
}

TEST(CandidatesReference, SameOnSyntheticFrames) {
  synth::SynthParams p;
  p.frames = 8;
  p.people_min = 1;
  p.people_max = 4;
  p.seed = 21;
  synth::SynthSequence sequence(p);
  for (int i = 0; i < 8; ++i) {
    const cv::Mat1w depth = sequence.frame(i).depth_mm;
    const Segmentation s = segment_depth(depth, {});
    const int layers = static_cast<int>(s.layers.size());
    expect_same_runs(s.labels, layers, 6, std::vector<int>(static_cast<std::size_t>(layers) + 1, 40),
                     "frame " + std::to_string(i));
    std::vector<char> passing(static_cast<std::size_t>(depth.cols), 1);
    for (const DepthLayer& layer : s.layers) {
      const int fast = floor_trimmed_bottom(depth, s.labels, layer.label, 100, 400, 50, 470, 150.0, passing,
                                            layer.min_depth_mm, layer.max_depth_mm);
      EXPECT_EQ(fast, test::trim_floor_reference(depth, s.labels, layer.label, 100, 400, 50, 470, 150.0,
                                                 [](int) { return true; }));
    }
  }
}

}  // namespace
}  // namespace rdsf
