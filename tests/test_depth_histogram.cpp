// depth_histogram() (eight partial histograms kept zero between calls, the row maximum in SSE2, the
// candidate scan in the same pass) and scan_depth_candidate_row() (jumps found eight pixels at a time)
// against their straightforward versions: a histogram counted pixel by pixel, and the pixel-by-pixel scan
// that scan_depth_candidates() was before. Random maps with zeros, 65535 and runs of equal depths, widths that
// are not multiples of 8 or 16, submatrices with a row stride, repeated calls (the parts must be left zero),
// and scan parameters at and beyond their edges.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "rdsf/segmentation/depth_candidates.hpp"
#include "rdsf/segmentation/depth_histogram.hpp"
#include "rdsf/synth/synth_sequence.hpp"

namespace rdsf {
namespace {

// The scan as it was: every pixel tested for a jump from its left neighbour, then for holding.
std::vector<int> scan_reference(const cv::Mat1w& depth_mm, const SegmentationParams& p) {
  std::vector<int> candidates;
  const int width = depth_mm.cols;
  const int step = std::max(1, p.row_step);
  for (int row = 0; row < depth_mm.rows; row += step) {
    const std::uint16_t* d = depth_mm.ptr<std::uint16_t>(row);
    for (int j = p.left_border_jump ? 0 : 1; j + p.n < width; ++j) {
      const int value = d[j];
      if (j > 0 && std::abs(value - static_cast<int>(d[j - 1])) <= p.depth_threshold_mm) continue;
      bool holds = true;
      for (int m = 1; m <= p.n && holds; ++m) holds = std::abs(static_cast<int>(d[j + m]) - value) <= p.range_threshold_mm;
      if (holds) candidates.push_back(value);
    }
  }
  return candidates;
}

void expect_histogram(const cv::Mat1w& depth, const DepthHistogram& h, const std::string& what) {
  double max_value = 0;
  if (!depth.empty()) cv::minMaxLoc(depth, nullptr, &max_value);
  const std::size_t levels = static_cast<std::size_t>(max_value) + 1;
  std::vector<std::uint64_t> count(levels, 0);
  for (int r = 0; r < depth.rows; ++r) {
    for (int c = 0; c < depth.cols; ++c) ++count[depth(r, c)];
  }
  ASSERT_EQ(h.levels, levels) << what;
  ASSERT_EQ(h.count_before.size(), levels + 1) << what;
  ASSERT_EQ(h.depth_before.size(), levels + 1) << what;
  std::uint64_t n = 0, sum = 0;
  for (std::size_t x = 0; x <= levels; ++x) {
    ASSERT_EQ(h.count_before[x], n) << what << " at " << x;
    ASSERT_EQ(h.depth_before[x], sum) << what << " at " << x;
    if (x >= 1 && x < levels) n += count[x], sum += count[x] * x;
  }
}

cv::Mat1w random_map(std::mt19937& rng, int rows, int cols, int max_depth) {
  cv::Mat1w depth(rows, cols);
  std::uniform_int_distribution<int> value(0, max_depth);
  int run_value = value(rng);
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < cols; ++x) {
      const unsigned pick = rng() % 16;
      if (pick < 2) run_value = value(rng);  // runs of equal depths, as in real frames
      depth(y, x) = static_cast<std::uint16_t>(pick == 2 ? 0 : (pick == 3 ? max_depth : (pick == 4 ? value(rng) : run_value)));
    }
  }
  return depth;
}

TEST(DepthHistogram, SameAsCountingPixelByPixel) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 300; ++trial) {
    const int rows = 1 + static_cast<int>(rng() % 30), cols = 1 + static_cast<int>(rng() % 70);
    const int max_depth = trial % 4 == 0 ? 1 : (trial % 4 == 1 ? 40 : (trial % 4 == 2 ? 9000 : 65535));
    const cv::Mat1w depth = random_map(rng, rows, cols, max_depth);
    expect_histogram(depth, depth_histogram(depth), "random " + std::to_string(trial));
  }
  // All zeros, an empty map, and a submatrix (a row stride other than its width).
  expect_histogram(cv::Mat1w::zeros(7, 9), depth_histogram(cv::Mat1w::zeros(7, 9)), "zeros");
  expect_histogram(cv::Mat1w(), depth_histogram(cv::Mat1w()), "empty");
  const cv::Mat1w big = random_map(rng, 40, 90, 65535);
  const cv::Mat1w part = big(cv::Rect(3, 5, 61, 20));
  expect_histogram(part, depth_histogram(part), "submatrix");
}

TEST(DepthHistogram, ScansTheCandidateRowsInTheSamePass) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 300; ++trial) {
    const int rows = 1 + static_cast<int>(rng() % 30), cols = 1 + static_cast<int>(rng() % 70);
    const cv::Mat1w depth = random_map(rng, rows, cols, trial % 2 ? 65535 : 3000);
    SegmentationParams p;
    p.row_step = static_cast<int>(rng() % 5) - 1;  // -1 and 0 mean every row, as in scan_depth_candidates
    p.n = static_cast<int>(rng() % 9);               // 0 .. 8, also n >= width
    p.depth_threshold_mm = std::vector<int>{0, 1, 150, 2999, 65534, 65535, 70000}[rng() % 7];
    p.range_threshold_mm = static_cast<int>(rng() % 200);
    p.left_border_jump = rng() % 2 == 0;
    std::vector<int> in_pass;
    const DepthHistogram h = depth_histogram(depth, &p, &in_pass);
    const std::string what = "trial " + std::to_string(trial);
    EXPECT_EQ(in_pass, scan_reference(depth, p)) << what;
    EXPECT_EQ(scan_depth_candidates(depth, p), scan_reference(depth, p)) << what;
    expect_histogram(depth, h, what);
  }
}

TEST(DepthHistogram, ScanSameAsReferenceOnSyntheticFrames) {
  const synth::SynthParams s = synth::people_scene(6, 1, 4, 9);
  synth::SynthSequence sequence(s);
  for (int i = 0; i < s.frames; ++i) {
    const cv::Mat1w depth = sequence.frame(i).depth_mm;
    for (const bool border : {true, false}) {
      SegmentationParams p;
      p.left_border_jump = border;
      std::vector<int> in_pass;
      const DepthHistogram h = depth_histogram(depth, &p, &in_pass);
      EXPECT_EQ(in_pass, scan_reference(depth, p)) << i;
      expect_histogram(depth, h, "synthetic " + std::to_string(i));
    }
  }
}

}  // namespace
}  // namespace rdsf
