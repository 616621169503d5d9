// label_by_layer_starts() (starts counted per pixel in SSE2 up to kMaxVectorStarts, else a table) against
// its formula label(d) = #{k : b_k <= d}, and the segmentation built on it against the straightforward
// reference (tests/support/reference_segmentation.hpp) where the nearest-centre rule is tight: depths at
// the exact midpoint between two centres (a tie goes to the nearer, lower centre), a half millimetre either
// side, zeros, 1 and 65535, layers left empty, and every number of layers from 1 to 254.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "rdsf/segmentation/depth_layers.hpp"
#include "rdsf/segmentation/layer_labels.hpp"
#include "support/reference_segmentation.hpp"

namespace rdsf {
namespace {

std::uint8_t label_formula(std::uint16_t d, const std::vector<std::uint16_t>& starts) {
  int label = 0;
  for (const std::uint16_t b : starts) label += b <= d ? 1 : 0;
  return static_cast<std::uint8_t>(label);
}

std::vector<std::uint16_t> random_starts(std::mt19937& rng, std::size_t count) {
  std::set<std::uint16_t> chosen{1};
  const int pick = static_cast<int>(rng() % 3);
  while (chosen.size() < count) {
    // Spread over all values, crowded at the top (65535 a start), or close together.
    const std::uint32_t v = pick == 0 ? 1 + rng() % 65535 : (pick == 1 ? 65535 - rng() % 300 : 1 + rng() % 600);
    chosen.insert(static_cast<std::uint16_t>(v));
  }
  return {chosen.begin(), chosen.end()};
}

TEST(LayerLabels, SameAsTheFormula) {
  std::mt19937 rng(23);
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t count = 1 + rng() % (trial % 2 ? kMaxVectorStarts + 4 : 255);
    const std::vector<std::uint16_t> starts = random_starts(rng, count);
    const int rows = 1 + static_cast<int>(rng() % 20), cols = 1 + static_cast<int>(rng() % 80);
    cv::Mat1w depth(rows, cols);
    for (int y = 0; y < rows; ++y) {
      for (int x = 0; x < cols; ++x) {
        const unsigned pick = rng() % 6;
        const std::uint16_t b = starts[rng() % starts.size()];
        // Zeros, the extremes, a start itself and its neighbours (the edges of each count), anything.
        depth(y, x) = pick == 0 ? 0 : pick == 1 ? (rng() % 2 ? 65535 : 1)
                    : pick == 2 ? b : pick == 3 ? static_cast<std::uint16_t>(b - 1)
                    : pick == 4 ? static_cast<std::uint16_t>(std::min(65535, b + 1)) : static_cast<std::uint16_t>(rng());
      }
    }
    cv::Mat1b labels;
    label_by_layer_starts(depth, starts, labels);
    ASSERT_EQ(labels.size(), depth.size());
    for (int y = 0; y < rows; ++y) {
      for (int x = 0; x < cols; ++x) {
        ASSERT_EQ(labels(y, x), label_formula(depth(y, x), starts))
            << "trial " << trial << " starts " << starts.size() << " depth " << depth(y, x);
      }
    }
  }
}

TEST(LayerLabels, SegmentationSameAsReferenceAtTiesAndExtremes) {
  std::mt19937 rng(31);
  for (int trial = 0; trial < 300; ++trial) {
    // Centres at integers or half integers; depths at their midpoints and next to them.
    const std::size_t count = 1 + rng() % (trial % 3 ? 20 : 260);
    std::vector<double> centres;
    for (std::size_t k = 0; k < count; ++k) {
      const double c = trial % 5 == 0 ? 65535.0 - static_cast<double>(rng() % 4000) : 1.0 + static_cast<double>(rng() % 9000);
      centres.push_back(rng() % 2 ? c : c + 0.5);
    }
    std::vector<double> sorted = centres;
    std::sort(sorted.begin(), sorted.end());
    const int rows = 1 + static_cast<int>(rng() % 16), cols = 1 + static_cast<int>(rng() % 70);
    cv::Mat1w depth(rows, cols);
    for (int y = 0; y < rows; ++y) {
      for (int x = 0; x < cols; ++x) {
        const std::size_t k = rng() % sorted.size();
        const double mid = k + 1 < sorted.size() ? (sorted[k] + sorted[k + 1]) / 2 : sorted[k];
        const unsigned pick = rng() % 6;
        const double v = pick == 0 ? 0 : pick == 1 ? 65535 : pick == 2 ? std::floor(mid) : pick == 3 ? std::ceil(mid)
                       : pick == 4 ? std::floor(mid) - 1 : sorted[k];
        depth(y, x) = static_cast<std::uint16_t>(std::clamp(v, 0.0, 65535.0));
      }
    }
    for (const int cap : {1, 3, 30}) {
      const Segmentation fast = kmeans_layers(depth, centres, cap);
      const Segmentation reference = test::kmeans_layers_reference(depth, centres, cap);
      const std::string what = "trial " + std::to_string(trial) + " cap " + std::to_string(cap);
      ASSERT_EQ(fast.layers.size(), reference.layers.size()) << what;
      for (std::size_t i = 0; i < fast.layers.size(); ++i) {
        EXPECT_EQ(fast.layers[i].mean_depth_mm, reference.layers[i].mean_depth_mm) << what;
        EXPECT_EQ(fast.layers[i].pixel_count, reference.layers[i].pixel_count) << what;
        EXPECT_EQ(fast.layers[i].min_depth_mm, reference.layers[i].min_depth_mm) << what;
        EXPECT_EQ(fast.layers[i].max_depth_mm, reference.layers[i].max_depth_mm) << what;
      }
      EXPECT_EQ(fast.iterations, reference.iterations) << what;
      ASSERT_EQ(cv::countNonZero(fast.labels != reference.labels), 0) << what;
    }
  }
}

}  // namespace
}  // namespace rdsf
