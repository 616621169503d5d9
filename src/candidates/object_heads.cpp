#include "rdsf/candidates/object_heads.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace rdsf {

// Height (cm) above the object's lowest row of column c's highest pixel of the layer at or below the
// object's fitted top; 0 without one.
double top_profile_cm(const LayerShape& shape, const LayerObject& o, int c) {
  const LayerView& layer = shape.layer();
  for (int y = std::max(0, o.fit_top); y <= o.bottom; ++y) {
    if ((*layer.labels)(y, c) == layer.label) return layer.camera->height_cm(o.bottom - y + 1, layer.depth_mm_mean);
  }
  return 0.0;
}

// Heads (split_head.drop_cm; CandidateParams has the rule): the columns where a head tops the profile
// h of o.fit_first..o.fit_last, left to right.
std::vector<int> head_columns(const LayerShape& shape, const LayerObject& o, const std::vector<double>& h) {
  const HeadSplitParams& heads = shape.params().split_head;
  const int width = shape.width();
  const int n = static_cast<int>(h.size());
  const int head_px = std::max(2, shape.columns_px(heads.width_cm)), half = head_px / 2;
  const int min_gap = std::max(1, shape.columns_px(shape.params().min_part_width_cm));
  const double tallest = *std::max_element(h.begin(), h.end());
  const auto at = [&](int i) { return i >= 0 && i < n ? h[static_cast<std::size_t>(i)] : 0.0; };
  // Within head_px beyond `from` in direction `step`, the profile reaches top - drop (inside the extent,
  // or beyond it where the extent ends at the image's left or right border).
  const bool open_left = o.fit_first == 0, open_right = o.fit_last == width - 1;
  const auto drops = [&](int from, int step, double top) {
    for (int k = 1; k <= head_px; ++k) {
      const int j = from + step * k;
      if (j < 0) return open_left;
      if (j >= n) return open_right;
      if (at(j) <= top - heads.drop_cm) return true;
    }
    return false;
  };
  std::vector<int> found;
  for (int i = 0; i < n;) {
    const double top = at(i);
    bool peak = top > 0 && top >= 0.75 * tallest;
    for (int j = i - half; peak && j <= i + half; ++j) peak = at(j) <= top;
    if (!peak) {
      ++i;
      continue;
    }
    int end = i;  // the columns at this peak's height; the head is at their middle
    while (end + 1 < n && at(end + 1) == top) ++end;
    const int c = (i + end) / 2;
    int left = c, right = c;  // the head's top: the columns within 5 cm of its height
    while (left > 0 && at(left - 1) >= top - 5.0) --left;
    while (right + 1 < n && at(right + 1) >= top - 5.0) ++right;
    const double top_cm = shape.columns_cm(right - left + 1);
    if (right - left + 1 <= head_px && top_cm >= heads.min_width_cm && drops(left, -1, top) &&
        drops(right, 1, top)) {
      if (found.empty() || c - found.back() >= min_gap) {
        found.push_back(c);
      } else if (top > at(found.back())) {
        found.back() = c;
      }
    }
    i = end + 1;
  }
  for (int& c : found) c += o.fit_first;
  return found;
}

// The cut between two heads (the first column of the right piece), or -1 with fewer than two: between the
// neighbouring heads whose lower one rises the most above the lowest point of the profile between them,
// at the middle of the columns within 2 cm of that point, both pieces at least min_piece wide.
int cut_between_heads(const LayerShape& shape, const LayerObject& o, int min_piece) {
  const int a = o.fit_first, b = o.fit_last;
  std::vector<double> h(static_cast<std::size_t>(b - a + 1));
  for (int c = a; c <= b; ++c) h[static_cast<std::size_t>(c - a)] = top_profile_cm(shape, o, c);
  const std::vector<int> found = head_columns(shape, o, h);
  const auto at = [&](int c) { return h[static_cast<std::size_t>(c - a)]; };
  int best = -1;
  double best_dip = 0;
  for (std::size_t k = 0; k + 1 < found.size(); ++k) {
    const int lo = std::max(found[k] + 1, a + min_piece), hi = std::min(found[k + 1], b - min_piece + 1);
    if (lo > hi) continue;
    double lowest = std::numeric_limits<double>::max();
    for (int c = lo; c <= hi; ++c) lowest = std::min(lowest, at(c));
    const double dip = std::min(at(found[k]), at(found[k + 1])) - lowest;
    if (dip <= best_dip) continue;
    best_dip = dip;
    best = middle_of(lo, hi, [&](int c) { return at(c) <= lowest + 2.0; });
  }
  return best;
}

}  // namespace rdsf
