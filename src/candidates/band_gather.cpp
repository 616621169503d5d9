#include "rdsf/candidates/band_gather.hpp"

#include <algorithm>

#include "rdsf/candidates/band_gather_sse2.hpp"

namespace rdsf {
namespace {

template <typename Sum>
void gather_scalar(const cv::Mat1b& labels, const cv::Mat1w& depth_mm, int layer_label, int c0, int count, int row_lo,
                   int row_hi, int* in_count, int* first_row, Sum* depth_sum) {
  for (int y = row_lo; y <= row_hi; y += 2) {
    const std::uint8_t* label = labels.ptr<std::uint8_t>(y) + c0;
    const std::uint16_t* depth = depth_mm.ptr<std::uint16_t>(y) + c0;
    for (int j = 0; j < count; ++j) {
      const int in = label[j] == layer_label;
      first_row[j] = (in != 0 && first_row[j] < 0) ? y : first_row[j];
      in_count[j] += in;
      depth_sum[j] += static_cast<Sum>(in) * depth[j];
    }
  }
}

template <typename Sum>
void gather(const cv::Mat1b& labels, const cv::Mat1w& depth_mm, int label, int c0, int count, int row_lo, int row_hi,
            BandColumn* out, bool allow_sse2) {
  int in_count[kBandChunk + 1] = {}, first_row[kBandChunk + 1];
  Sum depth_sum[kBandChunk + 1] = {};
  std::fill(first_row, first_row + count, -1);
  bool done = false;
  if constexpr (sizeof(Sum) == 4) {
    if (allow_sse2 && band_sse2_available() && band_16_lanes(labels.cols, label, count, row_lo, row_hi)) {
      band_sse2(labels, depth_mm, label, c0, count, row_lo, row_hi, in_count, first_row, depth_sum);
      done = true;
    }
  }
  if (!done) gather_scalar<Sum>(labels, depth_mm, label, c0, count, row_lo, row_hi, in_count, first_row, depth_sum);
  for (int j = 0; j < count; ++j) out[j] = {in_count[j], first_row[j], static_cast<std::int64_t>(depth_sum[j])};
}

void gather_either(const cv::Mat1b& labels, const cv::Mat1w& depth_mm, int label, int c0, int count, int row_lo,
                   int row_hi, BandColumn* out, bool allow_sse2) {
  // Sums of at most 65,535 per pixel over every other row: exact in 32 bits below 131,072 rows.
  if (row_hi - row_lo < 131072) {
    gather<std::uint32_t>(labels, depth_mm, label, c0, count, row_lo, row_hi, out, allow_sse2);
  } else {
    gather<std::uint64_t>(labels, depth_mm, label, c0, count, row_lo, row_hi, out, allow_sse2);
  }
}

}  // namespace

bool band_16_lanes(int cols, int label, int count, int row_lo, int row_hi) {
  return row_hi - row_lo < 131072 && count <= 16 && cols >= 16 && label >= 0 && label <= 255 && row_hi <= 65535;
}

void gather_band(const cv::Mat1b& labels, const cv::Mat1w& depth_mm, int label, int c0, int count, int row_lo,
                 int row_hi, BandColumn* out) {
  gather_either(labels, depth_mm, label, c0, count, row_lo, row_hi, out, true);
}

void gather_band_scalar(const cv::Mat1b& labels, const cv::Mat1w& depth_mm, int label, int c0, int count,
                        int row_lo, int row_hi, BandColumn* out) {
  gather_either(labels, depth_mm, label, c0, count, row_lo, row_hi, out, false);
}

}  // namespace rdsf
