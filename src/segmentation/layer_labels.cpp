#include "rdsf/segmentation/layer_labels.hpp"

#include <algorithm>
#include <utility>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace rdsf {
namespace {

std::uint8_t counted_label(std::uint16_t d, const std::uint16_t* starts, std::size_t count) {
  std::uint8_t label = 0;
  for (std::size_t k = 0; k < count; ++k) label = static_cast<std::uint8_t>(label + (starts[k] <= d));
  return label;
}

void label_by_table(const cv::Mat1w& depth_mm, const std::vector<std::uint16_t>& starts, cv::Mat1b& labels) {
  std::uint16_t max_value = 0;
  for (int r = 0; r < depth_mm.rows; ++r) {
    const std::uint16_t* d = depth_mm.ptr<std::uint16_t>(r);
    for (int c = 0; c < depth_mm.cols; ++c) max_value = std::max(max_value, d[c]);
  }
  std::vector<std::uint8_t> table(std::size_t{max_value} + 1, 0);
  for (std::size_t k = 0; k < starts.size() && starts[k] <= max_value; ++k) {
    std::fill(table.begin() + starts[k], table.end(), static_cast<std::uint8_t>(k + 1));
  }
  const std::uint8_t* const lut = table.data();
  const int rows = depth_mm.rows, cols = depth_mm.cols;  // locals: the byte stores may alias anything
  for (int r = 0; r < rows; ++r) {
    const std::uint16_t* d = depth_mm.ptr<std::uint16_t>(r);
    std::uint8_t* out = labels.ptr<std::uint8_t>(r);
    int c = 0;
    for (; c + 4 <= cols; c += 4) {
      const std::uint8_t l0 = lut[d[c]], l1 = lut[d[c + 1]], l2 = lut[d[c + 2]], l3 = lut[d[c + 3]];
      out[c] = l0;
      out[c + 1] = l1;
      out[c + 2] = l2;
      out[c + 3] = l3;
    }
    for (; c < cols; ++c) out[c] = lut[d[c]];
  }
}

#ifdef __SSE2__
// K starts counted per pixel, 16 pixels a step; K a constant so that the counting is unrolled.
template <std::size_t K>
void label_by_counting(const cv::Mat1w& depth_mm, const std::vector<std::uint16_t>& starts, cv::Mat1b& labels) {
  const __m128i bias = _mm_set1_epi16(static_cast<short>(0x8000));
  __m128i below[K];  // (b - 1) ^ 0x8000: d >= b <=> (d ^ 0x8000) > below, signed
  for (std::size_t k = 0; k < K; ++k) below[k] = _mm_set1_epi16(static_cast<short>((starts[k] - 1) ^ 0x8000));
  const int rows = depth_mm.rows, cols = depth_mm.cols;
  for (int r = 0; r < rows; ++r) {
    const std::uint16_t* d = depth_mm.ptr<std::uint16_t>(r);
    std::uint8_t* out = labels.ptr<std::uint8_t>(r);
    int c = 0;
    for (; c + 16 <= cols; c += 16) {
      const __m128i a = _mm_xor_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(d + c)), bias);
      const __m128i b = _mm_xor_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(d + c + 8)), bias);
      __m128i la = _mm_setzero_si128(), lb = _mm_setzero_si128();
      for (std::size_t k = 0; k < K; ++k) {
        la = _mm_sub_epi16(la, _mm_cmpgt_epi16(a, below[k]));
        lb = _mm_sub_epi16(lb, _mm_cmpgt_epi16(b, below[k]));
      }
      _mm_storeu_si128(reinterpret_cast<__m128i*>(out + c), _mm_packus_epi16(la, lb));
    }
    for (; c < cols; ++c) out[c] = counted_label(d[c], starts.data(), K);
  }
}

template <std::size_t... K>
bool label_by_counting_upto(const cv::Mat1w& depth_mm, const std::vector<std::uint16_t>& starts, cv::Mat1b& labels,
                            std::index_sequence<K...>) {
  return ((starts.size() == K + 1 ? (label_by_counting<K + 1>(depth_mm, starts, labels), true) : false) || ...);
}
#endif

}  // namespace

void label_by_layer_starts(const cv::Mat1w& depth_mm, const std::vector<std::uint16_t>& starts, cv::Mat1b& labels) {
  labels.create(depth_mm.size());
#ifdef __SSE2__
  if (label_by_counting_upto(depth_mm, starts, labels, std::make_index_sequence<kMaxVectorStarts>{})) return;
#endif
  label_by_table(depth_mm, starts, labels);
}

}  // namespace rdsf
