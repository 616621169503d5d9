#pragma once
// Step 2 of the segmentation: k-means over depth, seeded with the merged depth candidates, whose clusters
// are the depth layers.
//
// The thesis runs cv::kmeans on all pixel depths with KMEANS_USE_INITIAL_LABELS, the initial labels being
// one assignment step to the depth candidates. Over one dimension that is Lloyd's algorithm, and Lloyd's
// algorithm only needs the histogram of depth values: assigning a depth value to its nearest centre and
// averaging per cluster gives the same centres and labels as doing it pixel by pixel. kmeans_layers() does
// exactly that (tests compare it with cv::kmeans on real frames), in well under a millisecond instead of
// hundreds. Over one dimension each cluster is an interval of depth values, so an iteration costs
// O(clusters) with prefix sums of the histogram (the same centres, bit for bit, as assigning every depth
// value: tests/test_segmentation_reference.cpp).
//
// Pixels without a reading (0) never join a layer: the "no reading" candidate stands for them and they
// keep label 0. Clusters that end up empty are dropped (cv::kmeans would re-seed them at random).
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/segmentation/depth_histogram.hpp"
#include "rdsf/segmentation/segmentation_params.hpp"

namespace rdsf {

struct DepthLayer {
  int label = 0;              ///< value of this layer's pixels in Segmentation::labels (1-based)
  double mean_depth_mm = 0;   ///< the cluster centre
  std::int64_t pixel_count = 0;
  std::uint16_t min_depth_mm = 0;  ///< nearest depth value assigned to the layer
  std::uint16_t max_depth_mm = 0;  ///< farthest depth value assigned to the layer
};

struct Segmentation {
  cv::Mat1b labels;                ///< per pixel: 0 = no reading, k = layers[k-1]
  std::vector<DepthLayer> layers;  ///< ordered by depth, nearest first
  std::vector<double> seeds_mm;    ///< the merged depth candidates that seeded k-means (without the 0)
  int iterations = 0;              ///< k-means iterations until no pixel changed layer

  /// 255 where the pixel belongs to layer `label`, else 0.
  cv::Mat1b mask(int label) const;
};

/// The centres k-means starts from: the positive ones of `centres_mm`, ascending, each once, at most 254
/// of them (the nearest: labels are 8-bit and 0 is "no reading"). Segmentation::seeds_mm.
std::vector<double> kmeans_seeds(const std::vector<double>& centres_mm);

/// One update of k-means's centres: sums[k] / counts[k] for every cluster k that holds pixels, in order (an
/// empty cluster is dropped, so the result may be shorter).
std::vector<double> kmeans_means(const std::vector<double>& sums, const std::vector<std::uint64_t>& counts);

/// Runs k-means over the valid depths of `depth_mm` from the given centres (mm, any order, zeros ignored).
/// At most 254 centres are used (the nearest ones).
Segmentation kmeans_layers(const cv::Mat1w& depth_mm, const std::vector<double>& centres_mm,
                           int max_iterations);

/// The same with `histogram` = depth_histogram(depth_mm) already made (segment_depth makes it in the pass
/// that scans for the candidates).
Segmentation kmeans_layers(const cv::Mat1w& depth_mm, const DepthHistogram& histogram,
                           const std::vector<double>& centres_mm, int max_iterations);

/// The whole segmentation: scan, merge, k-means (two passes over the map: the histogram with the scan's
/// rows, then the labels).
Segmentation segment_depth(const cv::Mat1w& depth_mm, const SegmentationParams& params);

}  // namespace rdsf
