#include <gtest/gtest.h>

#include <map>

#include <opencv2/core.hpp>

#include "rdsf/frame/frame_source.hpp"
#include "rdsf/segmentation/depth_candidates.hpp"
#include "rdsf/segmentation/depth_layers.hpp"
#include "support/depth_scenes.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

TEST(DepthLayers, PersonBeforeWallGivesTwoLayers) {
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {300, 100, 40, 360}, 2000);
  const Segmentation s = segment_depth(frame.depth_mm, SegmentationParams{});
  ASSERT_EQ(s.layers.size(), 2u);
  EXPECT_DOUBLE_EQ(s.layers[0].mean_depth_mm, 2000.0);
  EXPECT_EQ(s.layers[0].pixel_count, 40 * 360);
  EXPECT_DOUBLE_EQ(s.layers[1].mean_depth_mm, 4000.0);
  EXPECT_EQ(s.layers[1].pixel_count, 640 * 480 - 40 * 360);
  EXPECT_EQ(s.labels(200, 320), 1);
  EXPECT_EQ(s.labels(200, 100), 2);
  EXPECT_EQ(cv::countNonZero(s.mask(1)), 40 * 360);
}

TEST(DepthLayers, MissingReadingsJoinNoLayer) {
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {300, 100, 40, 360}, 2000);
  for (int y = 0; y < 480; y += 3) frame.depth_mm(y, (y * 7) % 640) = 0;
  const Segmentation s = segment_depth(frame.depth_mm, SegmentationParams{});
  ASSERT_EQ(s.layers.size(), 2u);  // the zeros make no layer of their own
  for (int y = 0; y < 480; y += 3) EXPECT_EQ(s.labels(y, (y * 7) % 640), 0);
}

TEST(DepthLayers, KmeansMovesSeedsToClusterMeans) {
  // Two depth populations 1000..1100 and 3000..3200; seeds deliberately off.
  cv::Mat1w depth(10, 100, std::uint16_t{0});
  for (int i = 0; i < 500; ++i) depth(i / 100, i % 100) = static_cast<std::uint16_t>(1000 + (i % 101));
  for (int i = 500; i < 1000; ++i) depth(i / 100, i % 100) = static_cast<std::uint16_t>(3000 + (i % 201));
  const Segmentation s = kmeans_layers(depth, {1500.0, 2500.0}, 30);
  ASSERT_EQ(s.layers.size(), 2u);
  double sum_near = 0, sum_far = 0;
  for (int i = 0; i < 500; ++i) sum_near += depth(i / 100, i % 100);
  for (int i = 500; i < 1000; ++i) sum_far += depth(i / 100, i % 100);
  EXPECT_NEAR(s.layers[0].mean_depth_mm, sum_near / 500, 1e-6);
  EXPECT_NEAR(s.layers[1].mean_depth_mm, sum_far / 500, 1e-6);
  EXPECT_GE(s.iterations, 1);
}

TEST(DepthLayers, EmptyClustersAreDropped) {
  cv::Mat1w depth(10, 10, std::uint16_t{2000});
  const Segmentation s = kmeans_layers(depth, {2000.0, 7000.0}, 30);
  ASSERT_EQ(s.layers.size(), 1u);
  EXPECT_EQ(s.layers[0].pixel_count, 100);
}

TEST(DepthLayers, NoSeedsNoLayers) {
  const Segmentation s = kmeans_layers(cv::Mat1w(10, 10, std::uint16_t{2000}), {}, 30);
  EXPECT_TRUE(s.layers.empty());
  EXPECT_EQ(cv::countNonZero(s.labels), 0);
}

// The seeds: positive, ascending, each once, the nearest 254 (kmeans_layers() and the reference in
// tests/support/reference_segmentation.hpp both start from them).
TEST(DepthLayers, SeedsArePositiveAscendingDistinctAndAtMost254) {
  EXPECT_EQ(kmeans_seeds({3000.0, 0.0, 1000.0, 3000.0, -5.0, 2000.5}), (std::vector<double>{1000.0, 2000.5, 3000.0}));
  EXPECT_TRUE(kmeans_seeds({0.0, -1.0}).empty());
  std::vector<double> many;
  for (int i = 300; i >= 1; --i) many.push_back(10.0 * i);
  const std::vector<double> seeds = kmeans_seeds(many);
  ASSERT_EQ(seeds.size(), 254u);
  EXPECT_EQ(seeds.front(), 10.0);
  EXPECT_EQ(seeds.back(), 2540.0);
  const Segmentation s = kmeans_layers(cv::Mat1w(4, 4, std::uint16_t{2000}), many, 30);
  EXPECT_EQ(s.seeds_mm, seeds);
}

// One update of the centres (both k-means share it): the mean of each cluster with pixels, empty ones dropped.
TEST(DepthLayers, MeansDropEmptyClustersAndKeepOrder) {
  EXPECT_EQ(kmeans_means({3000.0, 0.0, 9000.0}, {2, 0, 3}), (std::vector<double>{1500.0, 3000.0}));
  EXPECT_TRUE(kmeans_means({0.0}, {0}).empty());
}

// The histogram k-means must give the same layers as the thesis's cv::kmeans with initial labels.
TEST(DepthLayers, SameLayersAsOpenCvKmeansOnRealFrames) {
  RDSF_REQUIRE_REALDATA();
  auto source = open_frame_source((test::realdata_dir() / "people").string());
  DepthFrame frame;
  SegmentationParams params;
  int frames = 0;
  while (source->next(frame) && frames < 6) {
    ++frames;
    const std::vector<double> seeds =
        merge_depth_candidates(scan_depth_candidates(frame.depth_mm, params), params);
    const Segmentation ours = kmeans_layers(frame.depth_mm, seeds, 100);

    std::vector<double> centres;
    for (double s : seeds) {
      if (s > 0) centres.push_back(s);
    }
    cv::Mat1f data;
    std::vector<cv::Point> where;
    for (int y = 0; y < frame.depth_mm.rows; ++y) {
      for (int x = 0; x < frame.depth_mm.cols; ++x) {
        if (frame.depth_mm(y, x) == 0) continue;
        data.push_back(static_cast<float>(frame.depth_mm(y, x)));
        where.emplace_back(x, y);
      }
    }
    cv::Mat1i labels(data.rows, 1);
    for (int i = 0; i < data.rows; ++i) {  // one assignment step to the seeds: the initial labels
      int best = 0;
      for (int k = 1; k < static_cast<int>(centres.size()); ++k) {
        if (std::abs(data(i) - centres[k]) < std::abs(data(i) - centres[best])) best = k;
      }
      labels(i) = best;
    }
    cv::Mat centers;
    cv::kmeans(data, static_cast<int>(centres.size()), labels,
               cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 100, 0.0), 1,
               cv::KMEANS_USE_INITIAL_LABELS, centers);

    // Compare the partitions: each of our layers must map onto one OpenCV cluster.
    std::map<int, std::map<int, int>> votes;
    for (int i = 0; i < data.rows; ++i) ++votes[ours.labels(where[i])][labels(i)];
    int agree = 0;
    for (const auto& [layer, counts] : votes) {
      int best = 0, best_label = -1;
      for (const auto& [label, count] : counts) {
        if (count > best) best = count, best_label = label;
      }
      agree += best;
      ASSERT_GT(layer, 0);
      // OpenCV sums the centres in float (about 1 mm of rounding at these pixel counts).
      EXPECT_NEAR(ours.layers[layer - 1].mean_depth_mm, centers.at<float>(best_label), 2.0) << frame.name;
    }
    EXPECT_GE(static_cast<double>(agree) / data.rows, 0.999) << frame.name;
  }
  EXPECT_EQ(frames, 6);
}
