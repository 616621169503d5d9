// kmeans_layers() (clusters kept as intervals of depth values, prefix sums of the histogram) against the
// straightforward histogram k-means it replaced (tests/support/reference_segmentation.hpp): the same
// labels, layers, seeds and iteration count, bit for bit, on real and synthetic frames, on random depth
// maps with random seeds, with seeds that leave clusters empty, and with the iteration cap reached.
#include <gtest/gtest.h>

#include <random>

#include "rdsf/frame/frame_source.hpp"
#include "rdsf/segmentation/depth_candidates.hpp"
#include "rdsf/segmentation/depth_layers.hpp"
#include "rdsf/synth/synth_sequence.hpp"
#include "support/reference_segmentation.hpp"
#include "support/test_support.hpp"

namespace rdsf {
namespace {

void expect_same(const Segmentation& fast, const Segmentation& reference, const std::string& what) {
  ASSERT_EQ(fast.layers.size(), reference.layers.size()) << what;
  for (std::size_t i = 0; i < fast.layers.size(); ++i) {
    const DepthLayer& a = fast.layers[i];
    const DepthLayer& b = reference.layers[i];
    EXPECT_EQ(a.label, b.label) << what;
    EXPECT_EQ(a.mean_depth_mm, b.mean_depth_mm) << what << " layer " << i;  // the same bits
    EXPECT_EQ(a.pixel_count, b.pixel_count) << what;
    EXPECT_EQ(a.min_depth_mm, b.min_depth_mm) << what;
    EXPECT_EQ(a.max_depth_mm, b.max_depth_mm) << what;
  }
  EXPECT_EQ(fast.seeds_mm, reference.seeds_mm) << what;
  EXPECT_EQ(fast.iterations, reference.iterations) << what;
  ASSERT_EQ(fast.labels.size(), reference.labels.size()) << what;
  EXPECT_EQ(cv::countNonZero(fast.labels != reference.labels), 0) << what;
}

void compare_on(const cv::Mat1w& depth, const std::vector<double>& seeds, int max_iterations, const std::string& what) {
  expect_same(kmeans_layers(depth, seeds, max_iterations), test::kmeans_layers_reference(depth, seeds, max_iterations),
              what);
}

std::vector<double> thesis_seeds(const cv::Mat1w& depth) {
  const SegmentationParams params;
  return merge_depth_candidates(scan_depth_candidates(depth, params), params);
}

TEST(SegmentationReference, SameAsReferenceOnSyntheticFrames) {
  const synth::SynthParams p = synth::people_scene(12, 1, 4, 3);
  synth::SynthSequence sequence(p);
  for (int i = 0; i < 12; ++i) {
    const cv::Mat1w depth = sequence.frame(i).depth_mm;
    for (const int cap : {1, 2, 3, 30}) compare_on(depth, thesis_seeds(depth), cap, "synthetic " + std::to_string(i));
  }
}

TEST(SegmentationReference, SameAsReferenceOnRandomMapsAndSeeds) {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 200; ++trial) {
    const int rows = 1 + static_cast<int>(rng() % 40), cols = 1 + static_cast<int>(rng() % 60);
    const int max_depth = trial % 3 == 0 ? 20 : (trial % 3 == 1 ? 9000 : 65535);
    cv::Mat1w depth(rows, cols);
    std::uniform_int_distribution<int> value(0, max_depth), base(0, max_depth);
    // Patches of constant depth and noise, some pixels without reading.
    const int patches = 1 + static_cast<int>(rng() % 6);
    std::vector<int> levels;
    for (int k = 0; k < patches; ++k) levels.push_back(base(rng));
    for (int y = 0; y < rows; ++y) {
      for (int x = 0; x < cols; ++x) {
        const unsigned pick = rng() % 10;
        depth(y, x) = static_cast<std::uint16_t>(pick == 0 ? 0 : (pick == 1 ? value(rng) : levels[(x * patches) / cols]));
      }
    }
    std::vector<double> seeds;
    const int seed_count = static_cast<int>(rng() % 12);
    std::uniform_real_distribution<double> seed(0.0, max_depth * 1.2 + 5);
    for (int k = 0; k < seed_count; ++k) seeds.push_back(trial % 2 ? std::floor(seed(rng)) : seed(rng));
    for (const int cap : {1, 2, 30}) compare_on(depth, seeds, cap, "random " + std::to_string(trial));
  }
}

TEST(SegmentationReference, SameAsReferenceWithManySeeds) {
  std::mt19937 rng(2);
  cv::Mat1w depth(48, 64);
  cv::randu(depth, 0, 4000);
  std::vector<double> seeds;
  for (int k = 0; k < 400; ++k) seeds.push_back(1 + rng() % 5000);  // more than the 254 labels
  compare_on(depth, seeds, 30, "400 seeds");
}

TEST(SegmentationReference, SameAsReferenceOnRealFrames) {
  RDSF_REQUIRE_REALDATA();
  for (const char* group : {"people", "empty"}) {
    auto source = open_frame_source((test::realdata_dir() / group).string());
    DepthFrame frame;
    while (source->next(frame)) compare_on(frame.depth_mm, thesis_seeds(frame.depth_mm), 30, frame.name);
  }
}

}  // namespace
}  // namespace rdsf
