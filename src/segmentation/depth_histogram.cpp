#include "rdsf/segmentation/depth_histogram.hpp"

#include <algorithm>

#include "rdsf/segmentation/depth_candidates.hpp"

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace rdsf {
namespace {

constexpr std::size_t kValues = 65536;
// The partial histograms lie kStride counters apart: not a multiple of 4 KiB, so that the same depth in two
// of them is neither at the same cache set nor aliased by the 4 KiB address check of loads against stores.
constexpr std::size_t kStride = kValues + 72;
constexpr std::size_t kParts = 8;  // partial histograms: neighbouring equal depths count on different ones

std::uint16_t row_max(const std::uint16_t* d, int cols) {
  int c = 0;
  std::uint16_t best = 0;
#ifdef __SSE2__
  // Unsigned maximum through the signed one: x ^ 0x8000 keeps the order of unsigned x as signed.
  const __m128i bias = _mm_set1_epi16(static_cast<short>(0x8000));
  __m128i m0 = bias, m1 = bias;  // bias ^ bias = 0, the smallest value
  for (; c + 16 <= cols; c += 16) {
    m0 = _mm_max_epi16(m0, _mm_xor_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(d + c)), bias));
    m1 = _mm_max_epi16(m1, _mm_xor_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(d + c + 8)), bias));
  }
  __m128i m = _mm_max_epi16(m0, m1);
  m = _mm_max_epi16(m, _mm_srli_si128(m, 8));
  m = _mm_max_epi16(m, _mm_srli_si128(m, 4));
  m = _mm_max_epi16(m, _mm_srli_si128(m, 2));
  best = static_cast<std::uint16_t>(_mm_cvtsi128_si32(m) ^ 0x8000);
#endif
  for (; c < cols; ++c) best = d[c] > best ? d[c] : best;
  return best;
}

}  // namespace

DepthHistogram depth_histogram(const cv::Mat1w& depth_mm, const SegmentationParams* scan, std::vector<int>* candidates) {
  // kParts partial histograms of every value, zero on entry and left zero on return.
  thread_local std::vector<std::uint32_t> parts(kParts * kStride, 0);
  std::uint32_t* const h = parts.data();

  DepthHistogram histogram;
  const int rows = depth_mm.rows, cols = depth_mm.cols;
  const int step = scan != nullptr ? std::max(1, scan->row_step) : 0;
  std::uint16_t max_value = 0;
  for (int r = 0; r < rows; ++r) {
    const std::uint16_t* d = depth_mm.ptr<std::uint16_t>(r);
#ifdef __SSE2__
    if (r + 1 < rows) {  // the next row on its way from memory while this one is counted
      const char* ahead = reinterpret_cast<const char*>(depth_mm.ptr<std::uint16_t>(r + 1));
      for (std::size_t b = 0; b < std::size_t(cols) * sizeof(std::uint16_t); b += 64) _mm_prefetch(ahead + b, _MM_HINT_T0);
    }
#endif
    if (step != 0 && r % step == 0) scan_depth_candidate_row(d, cols, *scan, *candidates);
    max_value = std::max(max_value, row_max(d, cols));
    int c = 0;
    for (; c + 8 <= cols; c += 8) {
      ++h[d[c]];
      ++h[kStride + d[c + 1]];
      ++h[2 * kStride + d[c + 2]];
      ++h[3 * kStride + d[c + 3]];
      ++h[4 * kStride + d[c + 4]];
      ++h[5 * kStride + d[c + 5]];
      ++h[6 * kStride + d[c + 6]];
      ++h[7 * kStride + d[c + 7]];
    }
    for (; c < cols; ++c) ++h[d[c]];
  }

  const std::size_t levels = std::size_t{max_value} + 1;
  histogram.levels = levels;
  try {
    histogram.count_before.assign(levels + 1, 0);
    histogram.depth_before.assign(levels + 1, 0);
  } catch (...) {
    std::fill(parts.begin(), parts.end(), 0u);  // the next call needs them zero
    throw;
  }
  std::uint64_t* const count = histogram.count_before.data();
  std::uint64_t* const depth = histogram.depth_before.data();
  for (std::size_t part = 0; part < kParts; ++part) h[part * kStride] = 0;  // no reading
  // The parts summed (and cleared) four values at a time; each sum below 2^32, as the number of pixels is.
  std::size_t x = 1;
  const auto accumulate = [&](std::size_t value, std::uint32_t n) {
    count[value + 1] = count[value] + n;
    depth[value + 1] = depth[value] + std::uint64_t{n} * value;
  };
#ifdef __SSE2__
  const __m128i zero = _mm_setzero_si128();
  for (; x + 4 <= levels; x += 4) {
    __m128i n = zero;
    for (std::size_t part = 0; part < kParts; ++part) {
      __m128i* at = reinterpret_cast<__m128i*>(h + part * kStride + x);
      n = _mm_add_epi32(n, _mm_loadu_si128(at));
      _mm_storeu_si128(at, zero);
    }
    alignas(16) std::uint32_t sums[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(sums), n);
    for (std::size_t i = 0; i < 4; ++i) accumulate(x + i, sums[i]);
  }
#endif
  for (; x < levels; ++x) {
    std::uint32_t n = 0;
    for (std::size_t part = 0; part < kParts; ++part) {
      n += h[part * kStride + x];
      h[part * kStride + x] = 0;
    }
    accumulate(x, n);
  }
  return histogram;
}

}  // namespace rdsf
