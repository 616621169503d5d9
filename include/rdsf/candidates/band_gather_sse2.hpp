#pragma once
// The SSE2 kernel of gather_band() (band_gather.hpp), apart from the logic that calls it.
#include <cstdint>

#include <opencv2/core.hpp>

namespace rdsf {

/// True when this build has the SSE2 kernel (x86-64 always does).
bool band_sse2_available();

/// gather_band()'s counts for columns c0..c0 + count - 1 in 16 lanes, only where band_16_lanes() holds:
/// lane i is column base + i, base = min(c0, cols - 16), so that the 16 columns read lie inside the row.
/// Per lane: the count in 8-bit lanes, added into 16-bit ones every 255 rows (at most 65,535 rows every
/// other one: 16 bits suffice); the first row as a 16-bit row index kept while no earlier row held the
/// layer (-1 when none); the depth sum in 32 bits. Writes in_count, first_row, depth_sum [0..count-1].
/// Without SSE2 it does nothing (band_sse2_available() is false).
void band_sse2(const cv::Mat1b& labels, const cv::Mat1w& depth_mm, int label, int c0, int count, int row_lo,
               int row_hi, int* in_count, int* first_row, std::uint32_t* depth_sum);

}  // namespace rdsf
