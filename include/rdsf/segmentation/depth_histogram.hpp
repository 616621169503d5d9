#pragma once
// The histogram of a depth map's valid values (1..max), kept as prefix sums: what k-means over depth needs
// (tests/test_segmentation_reference.cpp compares the layers built on it with a pixel-by-pixel reference).
//
//   count_before[x] = #{pixels p : 1 <= d(p) < x}          (x = 0 .. levels)
//   depth_before[x] = sum of d(p) over the same pixels      (exact integers: at most 2^32 pixels x 65535)
//   levels          = max d(p) + 1 (1 for an all-zero or empty map)
//
// So a cluster holding the depth values [a, b) has count_before[b] - count_before[a] pixels whose depths sum
// to depth_before[b] - depth_before[a], and the values that occur are those x with count_before[x + 1] >
// count_before[x]. Pixels without a reading (0) are not counted.
//
// One pass over the map, row by row: the next row prefetched, the row's maximum found eight values at a time
// (SSE2), the row counted into eight partial histograms of all 65536 values (pixel c into part c % 8; the
// parts lie 65536 + 72 counters apart, never a multiple of 4 KiB, so that one depth in two parts shares
// neither a cache set nor the 4 KiB alias check of loads against stores), kept zero between calls (per
// thread, 2 MiB), so that no pass for the maximum comes first and runs of equal depths (the common case) do
// not wait on one counter. The parts are summed and cleared up to the maximum only. The rows the
// depth-candidate scan reads are scanned in the same pass, while they are in cache. Maps of fewer than 2^32
// pixels (the part counters are 32-bit).
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/segmentation/segmentation_params.hpp"

namespace rdsf {

struct DepthHistogram {
  std::size_t levels = 1;
  std::vector<std::uint64_t> count_before;  ///< levels + 1 entries
  std::vector<std::uint64_t> depth_before;  ///< levels + 1 entries
};

/// The histogram of `depth_mm`. With `scan` set, also appends to `candidates` what
/// scan_depth_candidates(depth_mm, *scan) returns (the same values in the same order).
DepthHistogram depth_histogram(const cv::Mat1w& depth_mm, const SegmentationParams* scan = nullptr,
                               std::vector<int>* candidates = nullptr);

}  // namespace rdsf
