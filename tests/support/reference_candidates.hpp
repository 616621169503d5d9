#pragma once
// The straightforward candidate steps as they were before issue 17's speed-ups (src/candidates): the
// column runs with a byte-by-byte run scan and a pass over a column's segments per layer, the floor trim's
// median by collecting the depths and nth_element, the crops with a bounds test per pixel, and the fitted
// extent's walk counting each column's band when it reaches it. Kept as the references the tests compare
// the library with, result for result.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <cmath>

#include <opencv2/core.hpp>

#include "rdsf/candidates/candidate.hpp"
#include "rdsf/candidates/column_heights.hpp"
#include "rdsf/frame/depth_frame.hpp"

namespace rdsf::test {

struct ReferenceSegment {
  int label, first, last;  // rows first..last of one label
};

inline std::vector<std::vector<ColumnRun>> column_runs_reference(const cv::Mat1b& labels, int layer_count, int k,
                                                                const std::vector<int>& occlusion_gap_px = {},
                                                                const std::vector<int>& hole_gap_px = {}) {
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
      const int hole_limit =
          static_cast<std::size_t>(label) < hole_gap_px.size() ? hole_gap_px[static_cast<std::size_t>(label)] : 0;
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
        const bool holed = nothing_farther && !something_nearer && gap <= hole_limit;  // missing readings only
        if (start < 0 || (gap > k && !occluded && !holed)) start = s.first;
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

/// cut_crops() (candidates/candidate_finder.hpp) pixel by pixel.
inline void cut_crops_reference(const DepthFrame& frame, const cv::Mat1b& labels, int layer, const cv::Rect& window,
                                cv::Size crop_size, Candidate& candidate) {
  const bool colour = frame.has_colour();
  candidate.depth_crop = cv::Mat1w(crop_size);
  candidate.colour_crop = colour ? cv::Mat3b(crop_size) : cv::Mat3b();
  for (int v = 0; v < crop_size.height; ++v) {
    const int y = window.y + static_cast<int>(std::floor((v + 0.5) * window.height / crop_size.height));
    for (int u = 0; u < crop_size.width; ++u) {
      const int x = window.x + static_cast<int>(std::floor((u + 0.5) * window.width / crop_size.width));
      const bool inside = y >= 0 && y < frame.depth_mm.rows && x >= 0 && x < frame.depth_mm.cols && labels(y, x) == layer;
      candidate.depth_crop(v, u) = inside ? frame.depth_mm(y, x) : 0;
      if (colour) candidate.colour_crop(v, u) = inside ? frame.bgr(y, x) : cv::Vec3b(0, 0, 0);
    }
  }
}

struct FittedExtent {
  int first = 0, last = 0, top = 0;
};

/// The fitted extent of an object (LayerObject first..last, top..bottom; candidates/layer_objects.hpp,
/// step 1) within columns lo..hi: each side walks outwards from the object's edge column over columns
/// that do not pass, at most reach_px; a column continues the object when its band (rows
/// max(0, top - reach_px) .. top + 3 (bottom - top) / 4, every other one) holds at least two of the layer's
/// pixels whose mean depth is within depth_step_mm of the last column taken (any depth when that column's
/// band is empty or depth_step_mm <= 0); the walk stops after more than column_gap columns that do not.
inline FittedExtent fitted_extent_reference(const cv::Mat1b& labels, const cv::Mat1w& depth_mm, int layer,
                                            const std::vector<char>& passing, int first, int last, int top,
                                            int bottom, int reach_px, int column_gap, double depth_step_mm, int lo,
                                            int hi) {
  FittedExtent fitted{first, last, top};
  if (reach_px <= 0) return fitted;
  const int row_lo = std::max(0, top - reach_px), row_hi = std::min(labels.rows - 1, top + 3 * (bottom - top) / 4);
  struct Band {
    int count = 0, first_row = -1;
    double mean = 0;
  };
  const auto band = [&](int c) {
    Band b;
    double sum = 0;
    for (int y = row_lo; y <= row_hi; y += 2) {
      if (labels(y, c) != layer) continue;
      if (b.count++ == 0) b.first_row = y;
      sum += depth_mm(y, c);
    }
    b.mean = b.count > 0 ? sum / b.count : 0.0;
    return b;
  };
  for (int direction : {-1, 1}) {
    const int start = direction < 0 ? first : last;
    double previous = band(start).mean;
    int edge = start, gap = 0;
    for (int c = start + direction; c >= lo && c <= hi && std::abs(c - start) <= reach_px; c += direction) {
      if (passing[static_cast<std::size_t>(c)] != 0) break;
      const Band b = band(c);
      if (b.count >= 2 && (previous <= 0 || depth_step_mm <= 0 || std::abs(b.mean - previous) <= depth_step_mm)) {
        edge = c;
        gap = 0;
        fitted.top = std::min(fitted.top, b.first_row);
        previous = b.mean;
      } else if (++gap > column_gap) {
        break;
      }
    }
    (direction < 0 ? fitted.first : fitted.last) = edge;
  }
  return fitted;
}

}  // namespace rdsf::test
