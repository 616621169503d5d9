#pragma once
// The band gather of the fitted extent (layer_objects step 1, object_fit.hpp): for each of a few
// neighbouring columns, the pixels of one layer in a band of rows taken every other row - how many, the
// first row holding one, and the sum of their depths (mm). The SSE2 kernel and the scalar loop give the
// same numbers; which one runs is decided here, not by the caller.
#include <cstdint>

#include <opencv2/core.hpp>

namespace rdsf {

/// One column of the band: count = #{y in row_lo, row_lo + 2, ..., <= row_hi : labels(y, c) == label},
/// first_row = the smallest such y (-1 when count = 0), depth_sum = sum of depth_mm(y, c) over those y.
struct BandColumn {
  int count = 0, first_row = -1;
  std::int64_t depth_sum = 0;  ///< at most 65,535 per pixel over half the rows
};

/// Columns gathered at a time by the fitted extent (object_fit.cpp); one call takes at most kBandChunk + 1
/// (the first gather of a walk: the edge column and up to kBandChunk beside it).
constexpr int kBandChunk = 16;

/// The band's columns c0..c0 + count - 1 (0 < count <= kBandChunk + 1, inside the image; 0 <= row_lo,
/// row_hi < rows) into out[0..count-1], left to right. Sums are exact: in 32 bits while fewer than
/// 131,072 rows are spanned (at most 65,535 per pixel, every other row), else in 64 bits. In 16 SSE2
/// lanes when band_16_lanes() allows, else one column at a time without a branch on the data.
void gather_band(const cv::Mat1b& labels, const cv::Mat1w& depth_mm, int label, int c0, int count, int row_lo,
                 int row_hi, BandColumn* out);

/// gather_band() without the SSE2 kernel: the reference it must equal (exposed for tests).
void gather_band_scalar(const cv::Mat1b& labels, const cv::Mat1w& depth_mm, int label, int c0, int count,
                        int row_lo, int row_hi, BandColumn* out);

/// The 16-lane kernel holds: at most 16 columns, an image at least 16 wide (the 16 columns read may start
/// left of c0), a label that is a byte, row indices that are 16-bit (row_hi <= 65,535), 32-bit sums.
bool band_16_lanes(int cols, int label, int count, int row_lo, int row_hi);

}  // namespace rdsf
