#pragma once
// The straightforward candidate steps as they were before issue 17's speed-ups (src/candidates): the
// column runs with a byte-by-byte run scan, and the floor trim's median by collecting the depths and
// nth_element. Kept as the references the tests compare the library with, result for result.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/candidates/column_heights.hpp"

namespace rdsf::test {

struct ReferenceSegment {
  int label, first, last;  // rows first..last of one label
};

inline std::vector<std::vector<ColumnRun>> column_runs_reference(const cv::Mat1b& labels, int layer_count, int k,
                                                                const std::vector<int>& occlusion_gap_px = {}) {
  const int width = labels.cols, height = labels.rows;
  std::vector<std::vector<ColumnRun>> best(static_cast<std::size_t>(layer_count) + 1,
                                           std::vector<ColumnRun>(static_cast<std::size_t>(width)));
  // Columns as rows: one contiguous pass each.
  cv::Mat1b columns;
  cv::transpose(labels, columns);
  std::vector<ReferenceSegment> segments;
  std::vector<char> present(static_cast<std::size_t>(layer_count) + 1);
  for (int c = 0; c < width; ++c) {
    const std::uint8_t* column = columns.ptr<std::uint8_t>(c);
    segments.clear();
    std::fill(present.begin(), present.end(), 0);
    for (int r = 0; r < height;) {
      const int label = column[r];
      int end = r;
      while (end + 1 < height && column[end + 1] == label) ++end;
      segments.push_back({label, r, end});
      if (label > 0 && label <= layer_count) present[static_cast<std::size_t>(label)] = 1;
      r = end + 1;
    }
    for (int label = 1; label <= layer_count; ++label) {
      if (!present[static_cast<std::size_t>(label)]) continue;
      const int occlusion_limit =
          static_cast<std::size_t>(label) < occlusion_gap_px.size() ? occlusion_gap_px[static_cast<std::size_t>(label)] : 0;
      ColumnRun& b = best[static_cast<std::size_t>(label)][static_cast<std::size_t>(c)];
      int start = -1, last = -1;
      // Since `last`: no pixel of a farther layer, and some of a nearer one (missing readings are allowed
      // too: a Kinect leaves a shadow of no reading beside what stands in front).
      bool nothing_farther = true, something_nearer = false;
      for (const ReferenceSegment& s : segments) {
        if (s.label != label) {
          if (s.label > label) nothing_farther = false;
          if (s.label > 0 && s.label < label) something_nearer = true;
          continue;
        }
        const int gap = s.first - last - 1;
        const bool occluded = nothing_farther && something_nearer && gap <= occlusion_limit;
        if (start < 0 || (gap > k && !occluded)) start = s.first;
        last = s.last;
        nothing_farther = true;
        something_nearer = false;
        if (last - start + 1 > b.length()) {
          b.top = start;
          b.bottom = last;
        }
      }
    }
  }
  return best;
}


template <typename Passes>
inline int trim_floor_reference(const cv::Mat1w& depth_mm, const cv::Mat1b& labels, int layer, int first, int last, int top,
                                   int bottom, double tolerance_mm, const Passes& passes) {
  std::vector<std::uint16_t> depths;
  for (int r = top; r <= bottom; r += 2) {
    const std::uint8_t* label = labels.ptr<std::uint8_t>(r);
    const std::uint16_t* depth = depth_mm.ptr<std::uint16_t>(r);
    for (int c = first; c <= last; ++c) {
      if (label[c] == layer && passes(c)) depths.push_back(depth[c]);
    }
  }
  if (depths.empty()) return bottom;
  std::nth_element(depths.begin(), depths.begin() + static_cast<std::ptrdiff_t>(depths.size() / 2), depths.end());
  const double floor_below = depths[depths.size() / 2] - tolerance_mm;
  for (int r = bottom; r > top; --r) {
    const std::uint8_t* label = labels.ptr<std::uint8_t>(r);
    const std::uint16_t* depth = depth_mm.ptr<std::uint16_t>(r);
    int farthest = 0;
    for (int c = first; c <= last; ++c) {
      if (label[c] == layer && passes(c)) farthest = std::max(farthest, static_cast<int>(depth[c]));
    }
    if (farthest >= floor_below) return r;
  }
  return bottom;
}

}  // namespace rdsf::test
