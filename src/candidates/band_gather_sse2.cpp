#include "rdsf/candidates/band_gather_sse2.hpp"

#include <algorithm>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace rdsf {

#ifdef __SSE2__
bool band_sse2_available() { return true; }

void band_sse2(const cv::Mat1b& labels, const cv::Mat1w& depth_mm, int label, int c0, int count, int row_lo,
               int row_hi, int* in_count, int* first_row, std::uint32_t* depth_sum) {
  const int base = std::min(c0, labels.cols - 16), offset = c0 - base;
  const __m128i layer_v = _mm_set1_epi8(static_cast<char>(label));
  const __m128i zero = _mm_setzero_si128();
  __m128i count8 = zero, count_lo = zero, count_hi = zero;  // 16-bit counts of lanes 0-7 and 8-15
  __m128i seen_lo = zero, seen_hi = zero, first_lo = zero, first_hi = zero;
  __m128i sum0 = zero, sum1 = zero, sum2 = zero, sum3 = zero;  // 32-bit sums of lanes 0-3, 4-7, 8-11, 12-15
  int pending = 0;  // rows in count8
  const auto flush = [&]() {
    count_lo = _mm_add_epi16(count_lo, _mm_unpacklo_epi8(count8, zero));
    count_hi = _mm_add_epi16(count_hi, _mm_unpackhi_epi8(count8, zero));
    count8 = zero;
    pending = 0;
  };
  for (int y = row_lo; y <= row_hi; y += 2) {
    const std::uint8_t* row_labels = labels.ptr<std::uint8_t>(y) + base;
    const std::uint16_t* depth = depth_mm.ptr<std::uint16_t>(y) + base;
    const __m128i in = _mm_cmpeq_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(row_labels)), layer_v);
    count8 = _mm_sub_epi8(count8, in);
    const __m128i in_lo = _mm_unpacklo_epi8(in, in), in_hi = _mm_unpackhi_epi8(in, in);
    const __m128i row = _mm_set1_epi16(static_cast<short>(y));
    first_lo = _mm_or_si128(first_lo, _mm_and_si128(_mm_andnot_si128(seen_lo, in_lo), row));
    first_hi = _mm_or_si128(first_hi, _mm_and_si128(_mm_andnot_si128(seen_hi, in_hi), row));
    seen_lo = _mm_or_si128(seen_lo, in_lo);
    seen_hi = _mm_or_si128(seen_hi, in_hi);
    const __m128i d_lo = _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(depth)), in_lo);
    const __m128i d_hi = _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(depth + 8)), in_hi);
    sum0 = _mm_add_epi32(sum0, _mm_unpacklo_epi16(d_lo, zero));
    sum1 = _mm_add_epi32(sum1, _mm_unpackhi_epi16(d_lo, zero));
    sum2 = _mm_add_epi32(sum2, _mm_unpacklo_epi16(d_hi, zero));
    sum3 = _mm_add_epi32(sum3, _mm_unpackhi_epi16(d_hi, zero));
    if (++pending == 255) flush();
  }
  flush();
  alignas(16) std::uint16_t counts[16], firsts[16], seen[16];
  alignas(16) std::uint32_t sums[16];
  _mm_store_si128(reinterpret_cast<__m128i*>(counts), count_lo);
  _mm_store_si128(reinterpret_cast<__m128i*>(counts + 8), count_hi);
  _mm_store_si128(reinterpret_cast<__m128i*>(firsts), first_lo);
  _mm_store_si128(reinterpret_cast<__m128i*>(firsts + 8), first_hi);
  _mm_store_si128(reinterpret_cast<__m128i*>(seen), seen_lo);
  _mm_store_si128(reinterpret_cast<__m128i*>(seen + 8), seen_hi);
  _mm_store_si128(reinterpret_cast<__m128i*>(sums), sum0);
  _mm_store_si128(reinterpret_cast<__m128i*>(sums + 4), sum1);
  _mm_store_si128(reinterpret_cast<__m128i*>(sums + 8), sum2);
  _mm_store_si128(reinterpret_cast<__m128i*>(sums + 12), sum3);
  for (int j = 0; j < count; ++j) {
    const int lane = offset + j;
    in_count[j] = counts[lane];
    first_row[j] = seen[lane] != 0 ? firsts[lane] : -1;
    depth_sum[j] = sums[lane];
  }
}
#else
bool band_sse2_available() { return false; }

void band_sse2(const cv::Mat1b&, const cv::Mat1w&, int, int, int, int, int, int*, int*, std::uint32_t*) {}
#endif

}  // namespace rdsf
