#include "rdsf/candidates/floor_trim.hpp"

#include <algorithm>

namespace rdsf {
namespace {

constexpr int kDumpSlots = 8;  // counters for the pixels that do not count, in turn, so no chain forms

// The median by collecting the depths: for pixels outside the layer's range.
int collected_median(const cv::Mat1w& depth_mm, const cv::Mat1b& labels, int layer, int first, int last,
                     int top, int bottom, const std::vector<char>& passing, bool& any) {
  std::vector<std::uint16_t> depths;
  for (int r = top; r <= bottom; r += 2) {
    const std::uint8_t* label = labels.ptr<std::uint8_t>(r);
    const std::uint16_t* depth = depth_mm.ptr<std::uint16_t>(r);
    for (int c = first; c <= last; ++c) {
      if (label[c] == layer && passing[static_cast<std::size_t>(c)] != 0) depths.push_back(depth[c]);
    }
  }
  any = !depths.empty();
  if (!any) return 0;
  std::nth_element(depths.begin(), depths.begin() + static_cast<std::ptrdiff_t>(depths.size() / 2), depths.end());
  return depths[depths.size() / 2];
}

}  // namespace

int floor_trimmed_bottom(const cv::Mat1w& depth_mm, const cv::Mat1b& labels, int layer, int first, int last,
                         int top, int bottom, double tolerance_mm, const std::vector<char>& passing,
                         std::uint16_t layer_min_mm, std::uint16_t layer_max_mm) {
  const int lo = layer_min_mm;
  const int span = std::max(0, layer_max_mm - lo + 1);
  thread_local std::vector<std::uint32_t> histogram;
  histogram.assign(static_cast<std::size_t>(span + kDumpSlots), 0);
  std::uint32_t* const counts = histogram.data();
  const char* const passes = passing.data();
  bool outside = false;
  for (int r = top; r <= bottom; r += 2) {
    const std::uint8_t* label = labels.ptr<std::uint8_t>(r);
    const std::uint16_t* depth = depth_mm.ptr<std::uint16_t>(r);
    for (int c = first; c <= last; ++c) {
      const bool counted = label[c] == layer && passes[c] != 0;
      const int offset = depth[c] - lo;
      const bool in_range = static_cast<unsigned>(offset) < static_cast<unsigned>(span);
      outside = outside || (counted && !in_range);
      ++counts[counted && in_range ? offset + kDumpSlots : (c & (kDumpSlots - 1))];
    }
  }
  int median = 0;
  bool any = false;
  if (outside) {
    median = collected_median(depth_mm, labels, layer, first, last, top, bottom, passing, any);
  } else {
    std::uint64_t n = 0;
    for (int i = 0; i < span; ++i) n += counts[i + kDumpSlots];
    any = n > 0;
    std::uint64_t seen = 0;
    for (int i = 0; any && i < span; ++i) {
      seen += counts[i + kDumpSlots];
      if (seen > n / 2) {
        median = lo + i;
        break;
      }
    }
  }
  if (!any) return bottom;
  const double floor_below = median - tolerance_mm;
  for (int r = bottom; r > top; --r) {
    const std::uint8_t* label = labels.ptr<std::uint8_t>(r);
    const std::uint16_t* depth = depth_mm.ptr<std::uint16_t>(r);
    int farthest = 0;
    for (int c = first; c <= last; ++c) {
      if (label[c] == layer && passes[c] != 0) farthest = std::max(farthest, static_cast<int>(depth[c]));
    }
    if (farthest >= floor_below) return r;
  }
  return bottom;
}

}  // namespace rdsf
