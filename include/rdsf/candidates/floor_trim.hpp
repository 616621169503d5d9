#pragma once
// Floor trimming of an object's box (CandidateParams::floor_tolerance_mm): rows at the bottom of an object
// whose farthest layer pixel is nearer than the object's median depth by more than the tolerance hold only
// floor that lies before the feet, and are cut off the box.
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf {

/// The lowest row of the object (columns first..last whose passing[c] != 0, rows top..bottom) that is not
/// floor in front of it. The object's median depth m is the (n/2)-th smallest (0-based) of the n depths of
/// the layer's pixels in its passing columns, every other row from `top`; scanning up from `bottom`, the
/// first row whose farthest such pixel is at least m - tolerance_mm is returned (`bottom` when no pixel or
/// no row above `top` qualifies). Pixels of `layer` normally lie within layer_min_mm..layer_max_mm (as
/// kmeans_layers makes them): m is then counted in a histogram over that range, otherwise found by
/// nth_element over the collected depths; it is the same value either way.
int floor_trimmed_bottom(const cv::Mat1w& depth_mm, const cv::Mat1b& labels, int layer, int first, int last,
                         int top, int bottom, double tolerance_mm, const std::vector<char>& passing,
                         std::uint16_t layer_min_mm, std::uint16_t layer_max_mm);

}  // namespace rdsf
