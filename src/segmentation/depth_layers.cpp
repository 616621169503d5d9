#include "rdsf/segmentation/depth_layers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "rdsf/core/frame_buffers.hpp"
#include "rdsf/segmentation/depth_candidates.hpp"
#include "rdsf/segmentation/layer_labels.hpp"

namespace rdsf {
namespace {

// Over one dimension with ascending centres c_0 < c_1 < ..., the reference's assignment (every depth
// value d = 1, 2, ... moves on from centre k to k+1 while d - c_k > c_{k+1} - d) makes each cluster an
// interval of depth values. Each interval is kept as its end: cluster k holds the values
// ends[k-1] <= d < ends[k] (ends[-1] = 1, the last end = levels), so an iteration costs O(clusters)
// with prefix sums of the histogram instead of O(depth values).
std::int64_t first_beyond(double lower, double upper) {
  // The smallest d >= 1 with d - lower > upper - d, evaluated in doubles exactly as the reference does;
  // the predicate is monotone in d.
  const auto beyond = [&](std::int64_t d) {
    const double depth = static_cast<double>(d);
    return depth - lower > upper - depth;
  };
  std::int64_t d = std::max<std::int64_t>(1, static_cast<std::int64_t>(std::floor((lower + upper) / 2)));
  while (d > 1 && beyond(d - 1)) --d;
  while (!beyond(d)) ++d;
  return d;
}

void interval_ends(const std::vector<double>& centres, std::int64_t levels, std::vector<std::int64_t>& ends) {
  ends.resize(centres.size());
  std::int64_t previous = 1;
  for (std::size_t k = 0; k + 1 < centres.size(); ++k) {
    // The reference reaches centre k at d = previous and leaves it at the first d beyond from there.
    previous = std::min(levels, std::max(previous, first_beyond(centres[k], centres[k + 1])));
    ends[k] = previous;
  }
  ends.back() = levels;
}

// True when some depth value that occurs (a pixel) lies in clusters of different index under `a` and `b`.
bool partition_differs(const std::vector<std::int64_t>& a, const std::vector<std::int64_t>& b,
                       const std::vector<std::uint64_t>& count_before) {
  std::size_t i = 0, j = 0;
  std::int64_t at = 1;
  const std::int64_t levels = a.back();
  while (at < levels) {
    while (a[i] <= at) ++i;
    while (b[j] <= at) ++j;
    const std::int64_t next = std::min(a[i], b[j]);
    if (i != j && count_before[static_cast<std::size_t>(next)] != count_before[static_cast<std::size_t>(at)]) {
      return true;
    }
    at = next;
  }
  return false;
}

}  // namespace

cv::Mat1b Segmentation::mask(int label) const {
  cv::Mat1b out;
  cv::compare(labels, label, out, cv::CMP_EQ);
  return out;
}

std::vector<double> kmeans_seeds(const std::vector<double>& centres_mm) {
  std::vector<double> centres;
  for (double c : centres_mm) {
    if (c > 0) centres.push_back(c);
  }
  std::sort(centres.begin(), centres.end());
  centres.erase(std::unique(centres.begin(), centres.end()), centres.end());
  if (centres.size() > 254) centres.resize(254);  // labels are 8-bit; 0 is "no reading"
  return centres;
}

std::vector<double> kmeans_means(const std::vector<double>& sums, const std::vector<std::uint64_t>& counts) {
  std::vector<double> means;
  for (std::size_t k = 0; k < sums.size(); ++k) {
    if (counts[k] > 0) means.push_back(sums[k] / static_cast<double>(counts[k]));
  }
  return means;
}

Segmentation kmeans_layers(const cv::Mat1w& depth_mm, const std::vector<double>& centres_mm,
                           int max_iterations) {
  return kmeans_layers(depth_mm, depth_histogram(depth_mm), centres_mm, max_iterations);
}

Segmentation kmeans_layers(const cv::Mat1w& depth_mm, const DepthHistogram& histogram,
                           const std::vector<double>& centres_mm, int max_iterations) {
  Segmentation result;

  std::vector<double> centres = kmeans_seeds(centres_mm);
  result.seeds_mm = centres;
  if (centres.empty()) {
    result.labels = cv::Mat1b::zeros(depth_mm.size());
    return result;
  }

  const std::size_t levels = histogram.levels;
  const std::vector<std::uint64_t>& count_before = histogram.count_before;
  const std::vector<std::uint64_t>& depth_before = histogram.depth_before;
  const auto cluster_sums = [&](const std::vector<std::int64_t>& ends, std::vector<double>& sums,
                                std::vector<std::uint64_t>& counts) {
    sums.assign(ends.size(), 0.0);
    counts.assign(ends.size(), 0);
    std::size_t start = 1;
    for (std::size_t k = 0; k < ends.size(); ++k) {
      const auto end = static_cast<std::size_t>(ends[k]);
      counts[k] = count_before[end] - count_before[start];
      sums[k] = static_cast<double>(depth_before[end] - depth_before[start]);
      start = end;
    }
  };

  // Lloyd's algorithm on the histogram: initial labels = nearest seed, then centres <- means, labels <-
  // nearest centre, until no depth value changes cluster.
  const auto level_count = static_cast<std::int64_t>(levels);
  std::vector<std::int64_t> assignment, next;
  interval_ends(centres, level_count, assignment);
  std::vector<double> sums;
  std::vector<std::uint64_t> counts;
  for (int iteration = 0;; ++iteration) {
    cluster_sums(assignment, sums, counts);
    centres = kmeans_means(sums, counts);
    if (centres.empty()) {
      result.labels = cv::Mat1b::zeros(depth_mm.size());
      return result;
    }
    interval_ends(centres, level_count, next);
    const bool changed = partition_differs(assignment, next, count_before);
    // Cluster indices shift when a cluster was dropped; the pixel partition is what must be stable.
    if (!changed && centres.size() == sums.size()) {
      result.iterations = iteration + 1;
      break;
    }
    assignment.swap(next);
    if (iteration + 1 >= max_iterations) {
      result.iterations = iteration + 1;
      cluster_sums(assignment, sums, counts);  // final centres are the means of the final assignment
      break;
    }
  }

  // Layers: clusters with pixels, nearest first, labelled 1..K; each one's nearest and farthest depth, and
  // where its interval starts (the first one at 1: values below it occur in no pixel but 0).
  std::vector<std::uint16_t> starts;
  std::size_t start = 1;
  for (std::size_t k = 0; k < assignment.size(); ++k) {
    const auto end = static_cast<std::size_t>(assignment[k]);
    if (counts[k] > 0) {
      DepthLayer layer;
      layer.label = static_cast<int>(result.layers.size()) + 1;
      layer.mean_depth_mm = sums[k] / static_cast<double>(counts[k]);
      layer.pixel_count = static_cast<std::int64_t>(counts[k]);
      std::size_t lo = start, hi = end - 1;
      while (count_before[lo + 1] == count_before[lo]) ++lo;
      while (count_before[hi + 1] == count_before[hi]) --hi;
      layer.min_depth_mm = static_cast<std::uint16_t>(lo);
      layer.max_depth_mm = static_cast<std::uint16_t>(hi);
      starts.push_back(static_cast<std::uint16_t>(starts.empty() ? 1 : start));
      result.layers.push_back(layer);
    }
    start = end;
  }
  result.labels = frame_buffer(FrameBuffer::segmentation_labels, depth_mm.size(), CV_8UC1);  // every pixel written
  label_by_layer_starts(depth_mm, starts, result.labels);
  return result;
}

Segmentation segment_depth(const cv::Mat1w& depth_mm, const SegmentationParams& params) {
  // One pass over the map for the histogram and the scanned rows' candidates, one for the labels.
  std::vector<int> raw;
  const DepthHistogram histogram = depth_histogram(depth_mm, &params, &raw);
  return kmeans_layers(depth_mm, histogram, merge_depth_candidates(std::move(raw), params), params.max_iterations);
}

}  // namespace rdsf
