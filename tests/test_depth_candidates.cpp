#include <gtest/gtest.h>

#include <algorithm>

#include "rdsf/segmentation/depth_candidates.hpp"

using namespace rdsf;

TEST(DepthCandidates, JumpThatHoldsIsACandidate) {
  SegmentationParams p;  // depth_threshold 150, n 5, range_threshold 60, row_step 10
  cv::Mat1w depth(21, 40, std::uint16_t{3000});
  depth(cv::Rect(10, 0, 10, 21)).setTo(2000);  // a block: jumps at x=10 (to 2000) and x=20 (back to 3000)
  const std::vector<int> found = scan_depth_candidates(depth, p);
  // Rows 0, 10 and 20 are scanned; each gives 3000 (the border), 2000, then 3000.
  EXPECT_EQ(found, (std::vector<int>{3000, 2000, 3000, 3000, 2000, 3000, 3000, 2000, 3000}));
}

TEST(DepthCandidates, JumpThatDoesNotHoldIsIgnored) {
  SegmentationParams p;
  cv::Mat1w depth(1, 40, std::uint16_t{0});
  depth(cv::Rect(1, 0, 39, 1)).setTo(3000);
  depth(0, 10) = 1000;  // a single-pixel spike: jumps but does not hold for n pixels
  depth(0, 20) = 0;     // a single missing reading
  for (int x = 30; x < 40; ++x) depth(0, x) = static_cast<std::uint16_t>(3000 + (x - 29) * 100);  // a ramp
  // Only the returns to the wall after the border, the spike and the hole hold; the ramp's steps are small.
  EXPECT_EQ(scan_depth_candidates(depth, p), (std::vector<int>{3000, 3000, 3000}));
}

TEST(DepthCandidates, SmallStepsAreNotJumps) {
  SegmentationParams p;
  cv::Mat1w depth(1, 40, std::uint16_t{3000});
  depth(cv::Rect(10, 0, 30, 1)).setTo(3000 + p.depth_threshold_mm);  // exactly the threshold: not larger
  EXPECT_EQ(scan_depth_candidates(depth, p), std::vector<int>{3000});   // only the border
  depth(cv::Rect(10, 0, 30, 1)).setTo(3000 + p.depth_threshold_mm + 1);
  EXPECT_EQ(scan_depth_candidates(depth, p), (std::vector<int>{3000, 3000 + p.depth_threshold_mm + 1}));
}

TEST(DepthCandidates, OnlyEveryRowStepThRowIsScanned) {
  SegmentationParams p;
  cv::Mat1w depth(30, 40, std::uint16_t{3000});
  depth(cv::Rect(10, 5, 10, 1)).setTo(1000);  // row 5 is not scanned
  EXPECT_EQ(scan_depth_candidates(depth, p), (std::vector<int>{3000, 3000, 3000}));  // borders of rows 0, 10, 20
  p.row_step = 5;
  const std::vector<int> found = scan_depth_candidates(depth, p);
  EXPECT_EQ(std::count(found.begin(), found.end(), 1000), 1);
}

TEST(DepthCandidates, MergeSortsMergesZerosAndAveragesRuns) {
  SegmentationParams p;
  p.candidate_threshold_mm = 700;
  const std::vector<double> merged = merge_depth_candidates({3000, 0, 1650, 1000, 0, 1100, 0, 5200}, p);
  // 0 once; 1000, 1100, 1650 span 650 <= 700 -> their mean; 3000 alone; 5200 alone.
  ASSERT_EQ(merged.size(), 4u);
  EXPECT_EQ(merged[0], 0.0);
  EXPECT_NEAR(merged[1], (1000 + 1100 + 1650) / 3.0, 1e-9);
  EXPECT_EQ(merged[2], 3000.0);
  EXPECT_EQ(merged[3], 5200.0);
}

TEST(DepthCandidates, RunIsMeasuredFromItsFirstValue) {
  SegmentationParams p;
  p.candidate_threshold_mm = 300;
  // 1000..1300 is one run; 1400 starts the next even though it is only 100 from 1300.
  const std::vector<double> merged = merge_depth_candidates({1000, 1150, 1300, 1400, 1500}, p);
  ASSERT_EQ(merged.size(), 2u);
  EXPECT_NEAR(merged[0], 1150.0, 1e-9);
  EXPECT_NEAR(merged[1], 1450.0, 1e-9);
}

TEST(DepthCandidates, NoCandidatesMergeToNothing) {
  EXPECT_TRUE(merge_depth_candidates({}, SegmentationParams{}).empty());
}
