#include "rdsf/candidates/floor_trim.hpp"

#include <algorithm>
#include <utility>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace rdsf {
namespace {

// The histogram: kCopies copies side by side, copy q at counts[q * stride], stride = span + kDumps. A
// pixel (lane i of count_sse2()'s 8, position j of its range in count_scalar(): p below) is counted in
// copy p % kCopies, bin depth - lo when it belongs to the layer and lies in lo..lo + span - 1, else in
// the dump counter span + (p / kCopies) % kDumps of its copy (the increment is made anyway: no branch on
// the data). Neighbouring pixels of equal depth then do not wait for each other's increment; the sum
// over the copies is the one histogram, and its count n is every increment made but the dumps'.
constexpr int kCopies = 4;  // a power of two
constexpr int kDumps = 2;   // a power of two

// Counts positions from..n-1 of the range starting at column `begin` of one row; sets `outside` when a
// pixel of the layer lies outside the span.
inline void count_scalar(const std::uint8_t* label, const std::uint16_t* depth, int begin, int from, int n, int layer,
                         int lo, int span, std::uint32_t* counts, int stride, unsigned& outside) {
  for (int j = from; j < n; ++j) {
    const int c = begin + j;
    const unsigned counted = label[c] == layer;
    const int offset = depth[c] - lo;
    const unsigned in_range = static_cast<unsigned>(offset) < static_cast<unsigned>(span);
    outside |= counted & (in_range ^ 1u);
    const int copy = j & (kCopies - 1);
    const int bin = (counted & in_range) != 0 ? offset : span + ((j / kCopies) & (kDumps - 1));
    ++counts[copy * stride + bin];
  }
}

#ifdef __SSE2__
// count_scalar() for the n positions of a range, 8 pixels at a time in 16-bit lanes (span + kDumps <=
// 65,536, so every counter index is 16 bits), lane i counted in copy i % kCopies. The depth's offset wraps
// modulo 65,536; as lo + span <= 65,536 a depth below lo wraps to at least span, so "in the span" is the
// one unsigned comparison offset < span (signed after flipping the top bit: SSE2 has no unsigned one).
// The last n % 8 positions are counted by 8 lanes that end at the range's end (or, in a range shorter
// than 8, lie inside the row from min(begin, cols - 8)), those outside the positions not yet counted
// going to the dump counters. Returns the positions counted (n, or those of whole chunks when the row is
// narrower than 8 or wider than 32,767 columns: the lane's column is 16 bits) and adds every increment
// made to `increments`.
inline int count_sse2(const std::uint8_t* label, const std::uint16_t* depth, int begin, int n, int cols, int layer,
                      int lo, int span, std::uint32_t* counts, int stride, unsigned& outside,
                      std::uint64_t& increments) {
  const __m128i flip = _mm_set1_epi16(static_cast<short>(0x8000));
  const __m128i span_flipped = _mm_set1_epi16(static_cast<short>(span ^ 0x8000));
  const __m128i lo_v = _mm_set1_epi16(static_cast<short>(lo));
  const __m128i layer_v = _mm_set1_epi8(static_cast<char>(layer));
  static_assert(kCopies == 4 && kDumps == 2, "lanes 0-3 and 4-7 are the copies 0-3 with dumps span, span + 1");
  const __m128i dump_v = _mm_setr_epi16(static_cast<short>(span), static_cast<short>(span), static_cast<short>(span),
                                        static_cast<short>(span), static_cast<short>(span + 1),
                                        static_cast<short>(span + 1), static_cast<short>(span + 1),
                                        static_cast<short>(span + 1));
  std::uint32_t* const c0 = counts;
  std::uint32_t* const c1 = counts + stride;
  std::uint32_t* const c2 = counts + 2 * stride;
  std::uint32_t* const c3 = counts + 3 * stride;
  __m128i outside_v = _mm_setzero_si128();
  // The 8 pixels from column c whose lanes are set in `valid`.
  const auto chunk = [&](int c, __m128i valid) {
    const __m128i eq = _mm_cmpeq_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(label + c)), layer_v);
    const __m128i counted = _mm_and_si128(_mm_unpacklo_epi8(eq, eq), valid);
    const __m128i offset = _mm_sub_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(depth + c)), lo_v);
    const __m128i in_range = _mm_cmplt_epi16(_mm_xor_si128(offset, flip), span_flipped);
    const __m128i in = _mm_and_si128(counted, in_range);
    outside_v = _mm_or_si128(outside_v, _mm_andnot_si128(in_range, counted));
    const __m128i bin = _mm_or_si128(_mm_and_si128(in, offset), _mm_andnot_si128(in, dump_v));
    ++c0[_mm_extract_epi16(bin, 0)];
    ++c1[_mm_extract_epi16(bin, 1)];
    ++c2[_mm_extract_epi16(bin, 2)];
    ++c3[_mm_extract_epi16(bin, 3)];
    ++c0[_mm_extract_epi16(bin, 4)];
    ++c1[_mm_extract_epi16(bin, 5)];
    ++c2[_mm_extract_epi16(bin, 6)];
    ++c3[_mm_extract_epi16(bin, 7)];
    increments += 8;
  };
  const __m128i all = _mm_set1_epi16(-1);
  int j = 0;
  for (; j + 8 <= n; j += 8) chunk(begin + j, all);
  if (j < n && cols >= 8 && cols <= 32767) {
    const int start = n >= 8 ? begin + n - 8 : std::min(begin, cols - 8);
    const __m128i column = _mm_add_epi16(_mm_set1_epi16(static_cast<short>(start)), _mm_setr_epi16(0, 1, 2, 3, 4, 5, 6, 7));
    const __m128i from = _mm_set1_epi16(static_cast<short>(begin + j - 1)), to = _mm_set1_epi16(static_cast<short>(begin + n));
    chunk(start, _mm_and_si128(_mm_cmpgt_epi16(column, from), _mm_cmplt_epi16(column, to)));
    j = n;
  }
  outside |= _mm_movemask_epi8(outside_v) != 0;
  return j;
}
#endif

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
  // Labels are bytes: a layer outside 0..255 has no pixel (n = 0), nor has an object without passing columns.
  if (layer < 0 || layer > 255 || ranges.empty()) return bottom;
  const int stride = span + kDumps;
  // Every counter index in 16 bits (count_sse2); wider spans (depths of more than 65 m) collect instead.
  unsigned outside = stride > 65536 ? 1u : 0u;
  thread_local std::vector<std::uint32_t> histogram;
  histogram.assign(outside != 0 ? 0 : static_cast<std::size_t>(kCopies) * static_cast<std::size_t>(stride), 0);
  std::uint32_t* const counts = histogram.data();
  std::uint64_t increments = 0;  // counters incremented, dumps included
  for (int r = top; r <= bottom && outside == 0; r += 2) {
    const std::uint8_t* label = labels.ptr<std::uint8_t>(r);
    const std::uint16_t* depth = depth_mm.ptr<std::uint16_t>(r);
    for (const auto& range : ranges) {
      const int begin = range.first, n = range.second - range.first;
      int j = 0;
#ifdef __SSE2__
      j = count_sse2(label, depth, begin, n, labels.cols, layer, lo, span, counts, stride, outside, increments);
#endif
      count_scalar(label, depth, begin, j, n, layer, lo, span, counts, stride, outside);
      increments += static_cast<std::uint64_t>(n - j);
    }
  }
  int median = 0;
  bool any = false;
  if (outside) {
    median = collected_median(depth_mm, labels, layer, first, last, top, bottom, passing, any);
  } else {
    const auto bin = [&](int i) {
      std::uint64_t sum = 0;
      for (int q = 0; q < kCopies; ++q) sum += counts[q * stride + i];
      return sum;
    };
    // n: every increment made but those of the dump counters (no pass over the bins).
    std::uint64_t n = increments;
    for (int q = 0; q < kCopies; ++q) {
      for (int d = 0; d < kDumps; ++d) n -= counts[q * stride + span + d];
    }
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
