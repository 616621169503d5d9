#pragma once
// One layer as the object steps of layer_objects() see it (layer_objects.hpp): which columns pass the
// height test, the layer's units (cm <-> px at its mean depth), the object over a range of passing columns
// and a column's median depth. The fitting (object_fit.hpp) and head (object_heads.hpp) steps take it.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "rdsf/candidates/layer_objects.hpp"

namespace rdsf {

class LayerShape {
 public:
  /// Column c passes when camera.height_cm(run length, depth_mm_mean) >= threshold_height_cm(depth_mm_mean)
  /// - tested as "length >= the shortest passing length" (found by bisection over 0..longest + 1, the
  /// height growing with the length at a positive depth and fy) - or, with height_at_column_depth in layers
  /// nearer than column_depth_layers_below_mm, when it passes at depth_mm_max and at the median depth of
  /// its own run (every 4th row) - or when it passes as a column of a person the image cuts
  /// (BorderCutParams: its run reaches the image's top or bottom twentieth, is long and upright).
  LayerShape(const LayerView& layer, const CandidateParams& params);

  const LayerView& layer() const { return layer_; }
  const CandidateParams& params() const { return params_; }
  int width() const { return width_; }
  const std::vector<char>& passing() const { return passing_; }
  const ColumnRun& run(int c) const { return runs_[static_cast<std::size_t>(c)]; }
  bool passes(int c) const { return passing_[static_cast<std::size_t>(c)] != 0; }
  /// Width in cm of `columns` columns at the layer's mean depth (camera.width_cm: fx).
  double columns_cm(int columns) const { return layer_.camera->width_cm(columns, layer_.depth_mm_mean); }
  /// Columns of `centimetres` across at the layer's mean depth: trunc(cm * 10 * fx / max(1, depth_mm_mean)).
  int columns_px(double centimetres) const {
    return static_cast<int>(layer_.camera->columns_px(centimetres, std::max(1.0, layer_.depth_mm_mean)));
  }
  /// Rows of `centimetres` up or down at the layer's mean depth: trunc(cm * 10 * fy / max(1, depth_mm_mean)).
  /// columns_px and rows_px differ only where the pixels are not square (a frame stretched to another size).
  int rows_px(double centimetres) const {
    return static_cast<int>(layer_.camera->rows_px(centimetres, std::max(1.0, layer_.depth_mm_mean)));
  }
  /// columns_cm(o.last - o.first + 1) >= min_width_cm.
  bool wide_enough(const LayerObject& o) const { return columns_cm(o.last - o.first + 1) >= params_.min_width_cm; }
  /// The object over the passing columns of first..last (first and last pass): top/bottom the extremes of
  /// their runs, tallest the longest run, highest the middle one of the columns reaching top, and the
  /// fitted extent equal to first..last, top.
  LayerObject span(int first, int last) const;
  /// Median depth (the (n/2)-th smallest) of the layer's pixels in column c's run, every row_step-th row
  /// from its top; 0 when none.
  double column_depth_mm(int c, int row_step = 2) const;
  /// Median depth of the layer's pixels in the first (top) or last 8 rows of column c's run; 0 when none.
  double end_depth_mm(int c, bool top) const;

 private:
  const LayerView& layer_;
  const CandidateParams& params_;
  const std::vector<ColumnRun>& runs_;
  const int width_;
  std::vector<char> passing_;
  bool passes_as_cut_by_border(int c) const;  // BorderCutParams' rule
  /// Median depth of the layer's pixels in column c, rows from..to every row_step-th; 0 when none.
  double median_depth_mm(int c, int from, int to, int row_step) const;
  mutable std::vector<std::uint16_t> depths_;  // column_depth_mm()'s depths, reused
};

}  // namespace rdsf
