#include "rdsf/candidates/floor_trim.hpp"

#include <algorithm>
#include <utility>

namespace rdsf {
namespace {

constexpr int kDumpSlots = 8;  // counters for the pixels that do not count, in turn, so no chain forms
constexpr int kCopies = 4;     // interleaved copies of the histogram (a power of two)

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
  // The passing columns of first..last as ranges [begin, end): only those are read.
  thread_local std::vector<std::pair<int, int>> ranges;
  ranges.clear();
  for (int c = first; c <= last; ++c) {
    if (passing[static_cast<std::size_t>(c)] == 0) continue;
    if (!ranges.empty() && ranges.back().second == c) {
      ++ranges.back().second;
    } else {
      ranges.push_back({c, c + 1});
    }
  }
  const int lo = layer_min_mm;
  const int span = std::max(0, layer_max_mm - lo + 1);
  // kCopies interleaved histograms (bin i of copy j at kDumpSlots + i * kCopies + j, copy j counting the
  // columns c with c % kCopies == j), so that neighbouring pixels of equal depth do not wait for each
  // other's increment; their sum is the one histogram.
  thread_local std::vector<std::uint32_t> histogram;
  histogram.assign(static_cast<std::size_t>(kDumpSlots + span * kCopies), 0);
  std::uint32_t* const counts = histogram.data();
  // Per row and range: first every pixel's counter index (no branch on the data, so the compiler can
  // vectorise it), then the increments.
  thread_local std::vector<std::uint32_t> slots;
  unsigned outside = 0;
  for (int r = top; r <= bottom; r += 2) {
    const std::uint8_t* label = labels.ptr<std::uint8_t>(r);
    const std::uint16_t* depth = depth_mm.ptr<std::uint16_t>(r);
    for (const auto& range : ranges) {
      const int begin = range.first, n = range.second - range.first;
      if (slots.size() < static_cast<std::size_t>(n)) slots.resize(static_cast<std::size_t>(n));
      std::uint32_t* const slot = slots.data();
      for (int j = 0; j < n; ++j) {
        const int c = begin + j;
        const unsigned counted = label[c] == layer;
        const int offset = depth[c] - lo;
        const unsigned in_range = static_cast<unsigned>(offset) < static_cast<unsigned>(span);
        outside |= counted & (in_range ^ 1u);
        const unsigned dump = static_cast<unsigned>(c) & (kDumpSlots - 1);
        const unsigned bin = static_cast<unsigned>(kDumpSlots + offset * kCopies) + (static_cast<unsigned>(c) & (kCopies - 1));
        slot[j] = (counted & in_range) != 0 ? bin : dump;
      }
      for (int j = 0; j < n; ++j) ++counts[slot[j]];
    }
  }
  int median = 0;
  bool any = false;
  if (outside) {
    median = collected_median(depth_mm, labels, layer, first, last, top, bottom, passing, any);
  } else {
    const auto bin = [&](int i) {
      const std::uint32_t* b = counts + kDumpSlots + i * kCopies;
      std::uint64_t sum = 0;
      for (int j = 0; j < kCopies; ++j) sum += b[j];
      return sum;
    };
    std::uint64_t n = 0;
    for (int i = 0; i < span; ++i) n += bin(i);
    any = n > 0;
    std::uint64_t seen = 0;
    for (int i = 0; any && i < span; ++i) {
      seen += bin(i);
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
    for (const auto& range : ranges) {
      const int begin = range.first, end = range.second;
      for (int c = begin; c < end; ++c) farthest = std::max(farthest, label[c] == layer ? static_cast<int>(depth[c]) : 0);
    }
    if (farthest >= floor_below) return r;
  }
  return bottom;
}

}  // namespace rdsf
