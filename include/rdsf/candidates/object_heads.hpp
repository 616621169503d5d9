#pragma once
// Step 3's head rule of layer_objects() (layer_objects.hpp, split_head.drop_cm; CandidateParams has the
// rule in full): an object with two heads on top of its profile is cut between them.
#include <vector>

#include "rdsf/candidates/layer_shape.hpp"

namespace rdsf {

/// A cut column: (first + last + 1) / 2 of the first and last columns of lo..hi where near(c) holds (one
/// must).
template <typename Near>
int middle_of(int lo, int hi, Near near) {
  int first = -1, last = -1;
  for (int c = lo; c <= hi; ++c) {
    if (!near(c)) continue;
    if (first < 0) first = c;
    last = c;
  }
  return (first + last + 1) / 2;
}

/// Height (cm, camera.height_cm(o.bottom - y + 1, depth_mm_mean)) above the object's lowest row of the
/// highest row y of column c in max(0, o.fit_top)..o.bottom holding the layer; 0 without one.
double top_profile_cm(const LayerShape& shape, const LayerObject& o, int c);

/// The columns (image columns, left to right) where a head tops the profile h of o.fit_first..o.fit_last
/// (h[i] for column o.fit_first + i). With head_px = max(2, columns_px(split_head.width_cm)): a peak i has
/// h[i] > 0, h[i] >= 0.75 max(h) and no higher value within head_px / 2 either side; its head is the middle
/// of the columns at its height, its top the columns within 5 cm of it, which must be at most head_px and
/// at least split_head.min_width_cm wide, the profile dropping split_head.drop_cm below the peak within
/// head_px beyond each side (or the extent ending there at the image's border). Of two heads closer than
/// columns_px(min_part_width_cm) the higher stays (the first on a tie).
std::vector<int> head_columns(const LayerShape& shape, const LayerObject& o, const std::vector<double>& h);

/// The cut between two heads (the first column of the right piece), or -1 with fewer than two heads of
/// top_profile_cm(): between the neighbouring heads whose lower one rises the most above the lowest point
/// of the profile between them, at middle_of() the columns within 2 cm of that point, both pieces at least
/// min_piece wide.
int cut_between_heads(const LayerShape& shape, const LayerObject& o, int min_piece);

}  // namespace rdsf
