#include "rdsf/candidates/object_cut.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "rdsf/candidates/object_heads.hpp"

namespace rdsf {

// Height (cm) of the top of column c above the object's lowest row; 0 without a run in its rows.
double profile_cm(const LayerShape& shape, const LayerObject& o, int c) {
  const LayerView& layer = shape.layer();
  const ColumnRun& r = shape.run(c);
  if (r.length() == 0 || r.bottom < o.top || r.top > o.bottom) return 0.0;
  return layer.camera->height_cm(o.bottom - std::max(o.top, r.top) + 1, layer.depth_mm_mean);
}

// The best place to cut o.fit_first..o.fit_last (the first column of the right piece), or -1: the
// largest depth jump between neighbouring columns, else the deepest valley of the height profile, else
// the largest step between the mean heights of a person-wide band on each side.
int cut_wide(const LayerShape& shape, const LayerObject& o, int min_piece) {
  const CandidateParams& params = shape.params();
  const WideSplitParams& split = params.split;
  const int a = o.fit_first, b = o.fit_last;
  if (b - a + 1 < 2 * min_piece) return -1;
  const int lo = a + min_piece, hi = b - min_piece + 1;  // cut columns leaving both pieces wide enough
  if (split.depth_jump_mm > 0) {
    int best = -1;
    double best_jump = split.depth_jump_mm;
    double previous = shape.column_depth_mm(lo - 1);
    for (int c = lo; c <= hi; ++c) {
      const double depth = shape.column_depth_mm(c);
      if (depth > 0 && previous > 0 && std::abs(depth - previous) > best_jump) {
        best_jump = std::abs(depth - previous);
        best = c;
      }
      if (depth > 0) previous = depth;
    }
    if (best >= 0) return best;
  }
  std::vector<double> h(static_cast<std::size_t>(b - a + 1));
  for (int c = a; c <= b; ++c) h[static_cast<std::size_t>(c - a)] = profile_cm(shape, o, c);
  auto at = [&](int c) { return h[static_cast<std::size_t>(c - a)]; };
  if (split.valley_cm > 0) {
    std::vector<double> left(h.size()), right(h.size());
    for (std::size_t i = 0; i < h.size(); ++i) left[i] = std::max(h[i], i > 0 ? left[i - 1] : 0.0);
    for (std::size_t i = h.size(); i-- > 0;) right[i] = std::max(h[i], i + 1 < h.size() ? right[i + 1] : 0.0);
    double deepest = 0;
    for (int c = lo; c <= hi; ++c) {
      const std::size_t i = static_cast<std::size_t>(c - a);
      deepest = std::max(deepest, std::min(left[i], right[i]) - h[i]);
    }
    if (deepest >= split.valley_cm) {
      // The middle of the columns within 2 cm of the deepest point of the valley.
      return middle_of(lo, hi, [&](int c) {
        const std::size_t i = static_cast<std::size_t>(c - a);
        return std::min(left[i], right[i]) - h[i] >= deepest - 2.0;
      });
    }
  }
  if (split.step_cm > 0) {
    const int band = std::max(1, shape.columns_px(params.min_part_width_cm));
    int best = -1;
    double best_step = split.step_cm;
    for (int c = lo; c <= hi; ++c) {
      double sum_left = 0, sum_right = 0;
      int n_left = 0, n_right = 0;
      for (int x = std::max(a, c - band); x < c; ++x, ++n_left) sum_left += at(x);
      for (int x = c; x < std::min(b + 1, c + band); ++x, ++n_right) sum_right += at(x);
      const double step = std::abs(sum_left / std::max(1, n_left) - sum_right / std::max(1, n_right));
      if (step > best_step) {
        best_step = step;
        best = c;
      }
    }
    return best;
  }
  return -1;
}

}  // namespace rdsf
