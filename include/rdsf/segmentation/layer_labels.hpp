#pragma once
// The label pass of the segmentation: every pixel gets the label of the depth layer its value lies in.
//
// Over one dimension the layers are intervals of depth values, nearest first, and a pixel's value lies in a
// layer's interval (values between layers occur in no pixel). With the layer starts b_1 = 1 < b_2 < ... <
// b_K (b_k = the first depth value of layer k's interval, which begins where layer k-1's ends), the label
//
//   label(d) = #{k : b_k <= d}
//
// is 0 for no reading (d = 0) and k for every value of layer k: the nearest-centre rule the intervals come
// from, ties included, is already in the b_k. With at most kMaxVectorStarts starts it is counted eight
// pixels at a time (SSE2: unsigned d >= b as signed (d ^ 0x8000) > ((b - 1) ^ 0x8000), each true lane
// subtracting -1), else read from a table of all values; tests/test_layer_labels.cpp compares both with
// the formula on random maps, starts at 1 and 65535, zeros and the extreme values.
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf {

/// Starts counted per pixel up to this many (beyond: a table of labels per depth value).
constexpr std::size_t kMaxVectorStarts = 16;

/// Writes label(d) for every pixel of `depth_mm` into `labels` (allocated to its size). `starts` is strictly
/// ascending, its first element 1, at most 255 elements.
void label_by_layer_starts(const cv::Mat1w& depth_mm, const std::vector<std::uint16_t>& starts, cv::Mat1b& labels);

}  // namespace rdsf
