#pragma once
// The straightforward k-means over the depth histogram (as it was before the interval version in
// src/segmentation/depth_layers.cpp): every iteration assigns every depth value to its nearest centre and
// sums per cluster. Kept as the reference the tests compare kmeans_layers() with, bit for bit; it starts
// from the library's kmeans_seeds().
#include <algorithm>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/segmentation/depth_layers.hpp"

namespace rdsf::test {

// Assigns every depth value 1..max to the nearest centre (ties go to the nearer, i.e. lower, centre, as
// argmin does). `centres` is ascending. Returns the index of the centre per depth value (0 unused).
inline void assign_nearest_reference(const std::vector<double>& centres, std::vector<int>& assignment) {
  std::size_t k = 0;
  for (std::size_t d = 1; d < assignment.size(); ++d) {
    const double depth = static_cast<double>(d);
    while (k + 1 < centres.size() && depth - centres[k] > centres[k + 1] - depth) ++k;
    assignment[d] = static_cast<int>(k);
  }
}

inline Segmentation kmeans_layers_reference(const cv::Mat1w& depth_mm, const std::vector<double>& centres_mm,
                                              int max_iterations) {
  Segmentation result;
  result.labels = cv::Mat1b::zeros(depth_mm.size());

  std::vector<double> centres = kmeans_seeds(centres_mm);  // the seeds are the library's (tested apart)
  result.seeds_mm = centres;
  if (centres.empty()) return result;

  // Histogram of valid depth values.
  double max_value = 0;
  cv::minMaxLoc(depth_mm, nullptr, &max_value);
  const std::size_t levels = static_cast<std::size_t>(max_value) + 1;
  std::vector<std::uint32_t> histogram(levels, 0);
  for (int r = 0; r < depth_mm.rows; ++r) {
    const std::uint16_t* d = depth_mm.ptr<std::uint16_t>(r);
    for (int c = 0; c < depth_mm.cols; ++c) ++histogram[d[c]];
  }
  histogram[0] = 0;

  // Lloyd's algorithm on the histogram: initial labels = nearest seed, then centres <- means, labels <-
  // nearest centre, until no depth value changes cluster.
  std::vector<int> assignment(levels, 0);
  assign_nearest_reference(centres, assignment);
  std::vector<double> sums;
  std::vector<std::uint64_t> counts;
  const auto sum_clusters = [&] {  // per cluster of `assignment`: the sum of its depth values and their count
    sums.assign(centres.size(), 0.0);
    counts.assign(centres.size(), 0);
    for (std::size_t d = 1; d < levels; ++d) {
      sums[assignment[d]] += static_cast<double>(d) * histogram[d];
      counts[assignment[d]] += histogram[d];
    }
  };
  // Stable: no depth value that occurs changes cluster and no cluster was dropped (indices shift when one
  // is; the pixel partition is what must be stable). At least one iteration, at most max_iterations.
  bool stable = false;
  do {
    ++result.iterations;
    sum_clusters();
    centres = kmeans_means(sums, counts);  // the library's update (tested apart)
    if (centres.empty()) return result;
    std::vector<int> next(levels, 0);
    assign_nearest_reference(centres, next);
    bool moved = false;
    for (std::size_t d = 1; d < levels; ++d) moved = moved || (histogram[d] != 0 && next[d] != assignment[d]);
    stable = !moved && centres.size() == sums.size();
    if (!stable) assignment = next;
  } while (!stable && result.iterations < max_iterations);
  if (!stable) sum_clusters();  // the final centres are the means of the final assignment

  // Layers: clusters with pixels, nearest first, labelled 1..K.
  std::vector<int> label_of_cluster(centres.size(), 0);
  for (std::size_t k = 0; k < centres.size(); ++k) {
    if (counts[k] == 0) continue;
    DepthLayer layer;
    layer.label = static_cast<int>(result.layers.size()) + 1;
    layer.mean_depth_mm = sums[k] / static_cast<double>(counts[k]);
    layer.pixel_count = static_cast<std::int64_t>(counts[k]);
    label_of_cluster[k] = layer.label;
    result.layers.push_back(layer);
  }
  std::vector<std::uint8_t> lut(levels, 0);
  for (std::size_t d = 1; d < levels; ++d) {
    const int label = label_of_cluster[assignment[d]];
    lut[d] = static_cast<std::uint8_t>(label);
    if (histogram[d] == 0 || label == 0) continue;
    DepthLayer& layer = result.layers[label - 1];
    if (layer.min_depth_mm == 0) layer.min_depth_mm = static_cast<std::uint16_t>(d);
    layer.max_depth_mm = static_cast<std::uint16_t>(d);
  }
  for (int r = 0; r < depth_mm.rows; ++r) {
    const std::uint16_t* d = depth_mm.ptr<std::uint16_t>(r);
    std::uint8_t* out = result.labels.ptr<std::uint8_t>(r);
    for (int c = 0; c < depth_mm.cols; ++c) out[c] = lut[d[c]];
  }
  return result;
}

}  // namespace rdsf::test
