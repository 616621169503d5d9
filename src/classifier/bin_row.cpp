#include "rdsf/classifier/bin_row.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rdsf {

void bin_row(const BinScheme& bins, const float* values, int n, std::uint8_t* out) {
  int k = 0;
#if defined(__SSE2__)
  const __m128 min = _mm_set1_ps(bins.min_value), count = _mm_set1_ps(static_cast<float>(bins.count));
  const __m128 range = _mm_set1_ps(bins.max_value - bins.min_value);
  const __m128 top = _mm_set1_ps(static_cast<float>(bins.count - 1)), zero = _mm_setzero_ps();
  for (; k + 16 <= n; k += 16) {
    __m128i lanes[4];
    for (int q = 0; q < 4; ++q) {
      const __m128 scaled = _mm_div_ps(_mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(values + k + 4 * q), min), count), range);
      const __m128 positive = _mm_cmpgt_ps(scaled, zero);  // false for NaN
      // minps gives its second operand when either is NaN: top, then masked to 0 by `positive`
      lanes[q] = _mm_and_si128(_mm_cvttps_epi32(_mm_min_ps(scaled, top)), _mm_castps_si128(positive));
    }
    const __m128i words = _mm_packs_epi32(lanes[0], lanes[1]), words2 = _mm_packs_epi32(lanes[2], lanes[3]);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + k), _mm_packus_epi16(words, words2));  // 0..255
  }
#endif
  for (; k < n; ++k) out[k] = static_cast<std::uint8_t>(bins.bin_of(values[k]));
}

}  // namespace rdsf
