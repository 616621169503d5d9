#pragma once
// Step 4 of layer_objects() (layer_objects.hpp, narrow.fitted_width_cm): an object narrower than
// min_width_cm over its passing columns (a person whose legs alone pass threshold_height) stays one when
// it has a person's fitted width, height and depth and a background above its head.
#include "rdsf/candidates/layer_shape.hpp"

namespace rdsf {

/// Real width (cm, shape.columns_cm(n)) of the n passing columns of o.first..o.last alone, the gaps
/// between them left out; <= columns_cm(o.last - o.first + 1).
double passing_cm(const LayerShape& shape, const LayerObject& o);

/// The background above a head: over columns o.first..o.last and the band = max(1,
/// rows_px(narrow.clear_above_cm)) rows o.top - band .. o.top - 1 (rows: fy, not fx), at least half of the
/// pixels (2 other >= total, total > 0) hold a layer other than the object's (label != 0 and != layer.label).
/// Missing readings (label 0) and rows above the image count against it.
bool clear_above(const LayerShape& shape, const LayerObject& o);

/// With narrow.fitted_width_cm > 0 (else false): columns_cm(o.fit_last - o.fit_first + 1) >=
/// narrow.fitted_width_cm, columns_cm(o.last - o.first + 1) >= narrow.passing_width_cm, depth_mm_mean <
/// narrow.layers_below_mm, camera.height_cm(o.bottom - o.fit_top + 1, depth_mm_mean) >= narrow.min_height_cm
/// and clear_above(o).
/// It does not look at min_width_cm: layer_objects() asks it of objects that are not wide_enough().
bool narrow_person(const LayerShape& shape, const LayerObject& o);

}  // namespace rdsf
