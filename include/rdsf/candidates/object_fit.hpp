#pragma once
// Step 1 of layer_objects() (layer_objects.hpp, fit.reach_cm): the fitted extent of an object.
#include "rdsf/candidates/layer_shape.hpp"

namespace rdsf {

/// Sets o.fit_first, o.fit_last, o.fit_top. The fitted extent reaches over the columns beside the object
/// that hold its pieces (an arm, a hand): a column continues the object when the band - the layer's
/// pixels in rows max(0, top - reach) .. min(rows - 1, top + 3 (bottom - top) / 4), every other one -
/// holds at least two of them whose mean depth is within fit.depth_step_mm of the column last taken.
/// Gaps of up to column_gap columns are allowed, at most reach = columns_px(fit.reach_cm) columns each side,
/// never into a passing column nor beyond lo..hi. The fitted top rises to the highest band pixel taken.
/// A column that does not continue but shows something nearer (nearer_in_band() with at least
/// max(2, count of the column last taken / 2)) does not count towards the gap, for up to
/// columns_px(fit.occlusion_gap_cm) such columns in a row. Invariants: fit_first <= first, fit_last >= last,
/// fit_top <= top; reach <= 0 leaves first..last, top.
void fit_object(const LayerShape& shape, LayerObject& o, int lo, int hi);

/// At least `needed` pixels of nearer layers (labels 1..label - 1) in column c, rows row_lo, row_lo + 2,
/// ..., <= row_hi: something stands in front of the band there.
bool nearer_in_band(const LayerView& layer, int c, int row_lo, int row_hi, int needed);

}  // namespace rdsf
