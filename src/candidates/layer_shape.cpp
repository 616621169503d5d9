#include "rdsf/candidates/layer_shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rdsf {

LayerShape::LayerShape(const LayerView& layer, const CandidateParams& params)
    : layer_(layer), params_(params), runs_(*layer.runs), width_(static_cast<int>(layer.runs->size())) {
  const double min_height_cm = params.threshold_height_cm(layer.depth_mm_mean);
  passing_.resize(static_cast<std::size_t>(width_));
  int longest = 0;
  for (int c = 0; c < width_; ++c) longest = std::max(longest, run(c).length());
  // At depth d > 0 (and fy > 0) height_cm(length, d) grows with the length (each step of the formula
  // does), so "at least min_height_cm" is "length >= the shortest length that passes": found once by
  // bisection on the same formula over 0..longest (longest + 1 when none passes). Else (-1) every
  // column is measured.
  const auto shortest_passing = [&](double depth) {
    if (!(depth > 0) || !(layer.camera->fy_px > 0)) return -1;
    int lo = 0, hi = longest + 1;  // lengths below lo fail, lengths from hi on pass (or are none)
    while (lo < hi) {
      const int mid = lo + (hi - lo) / 2;
      if (layer.camera->height_cm(mid, depth) >= min_height_cm) {
        hi = mid;
      } else {
        lo = mid + 1;
      }
    }
    return lo;
  };
  const int shortest_at_mean = shortest_passing(layer.depth_mm_mean);
  const int shortest_at_max = shortest_passing(layer.depth_mm_max);
  const auto passes_at = [&](int length, double depth, int shortest) {
    return shortest >= 0 ? length >= shortest : layer.camera->height_cm(length, depth) >= min_height_cm;
  };
  for (int c = 0; c < width_; ++c) {
    const int length = run(c).length();
    bool passes = passes_at(length, layer.depth_mm_mean, shortest_at_mean);
    // A column that fails at the layer's mean depth may pass at its own (a layer spans up to
    // candidate_threshold of depth): measured where it could, at the median depth of its run.
    if (!passes && params.height_at_column_depth && length > 0 &&
        layer.depth_mm_mean < params.column_depth_layers_below_mm &&
        passes_at(length, layer.depth_mm_max, shortest_at_max)) {
      passes = layer.camera->height_cm(length, column_depth_mm(c, 4)) >= min_height_cm;
    }
    if (!passes && length > 0) passes = passes_as_cut_by_border(c);
    passing_[static_cast<std::size_t>(c)] = passes;
  }
}

bool LayerShape::passes_as_cut_by_border(int c) const {
  const BorderCutParams& b = params_.border;
  if (!(b.height_cm > 0)) return false;
  const ColumnRun& r = run(c);
  const int rows = layer_.labels->rows, band = rows / 20;
  if (r.top > band && r.bottom < rows - 1 - band) return false;  // reaches neither border
  if (r.length() < b.min_rows_fraction * rows) return false;
  if (layer_.camera->height_cm(r.length(), layer_.depth_mm_mean) < b.height_cm) return false;
  const double top = end_depth_mm(c, true), bottom = end_depth_mm(c, false);
  return top > 0 && bottom > 0 && std::abs(top - bottom) <= b.upright_mm;
}

double LayerShape::end_depth_mm(int c, bool top) const {
  const ColumnRun& r = run(c);
  return top ? median_depth_mm(c, r.top, std::min(r.bottom, r.top + 7), 1)
             : median_depth_mm(c, std::max(r.top, r.bottom - 7), r.bottom, 1);
}

LayerObject LayerShape::span(int first, int last) const {
  LayerObject o;
  o.first = first;
  o.last = last;
  o.top = std::numeric_limits<int>::max();
  o.bottom = -1;
  for (int x = first; x <= last; ++x) {
    if (!passes(x)) continue;
    o.top = std::min(o.top, run(x).top);
    o.bottom = std::max(o.bottom, run(x).bottom);
    o.tallest = std::max(o.tallest, run(x).length());
  }
  std::vector<int> at_top;
  for (int x = first; x <= last; ++x) {
    if (passes(x) && run(x).top == o.top) at_top.push_back(x);
  }
  o.highest = at_top[at_top.size() / 2];
  o.fit_first = first;
  o.fit_last = last;
  o.fit_top = o.top;
  return o;
}

double LayerShape::column_depth_mm(int c, int row_step) const {
  const ColumnRun& r = run(c);
  return median_depth_mm(c, r.top, r.bottom, row_step);
}

double LayerShape::median_depth_mm(int c, int from, int to, int row_step) const {
  std::vector<std::uint16_t>& depths = depths_;  // reused: called for many columns of a layer
  depths.clear();
  for (int y = from; y >= 0 && y <= to; y += row_step) {
    if ((*layer_.labels)(y, c) == layer_.label) depths.push_back((*layer_.depth_mm)(y, c));
  }
  if (depths.empty()) return 0.0;
  std::nth_element(depths.begin(), depths.begin() + static_cast<std::ptrdiff_t>(depths.size() / 2), depths.end());
  return depths[depths.size() / 2];
}

}  // namespace rdsf
