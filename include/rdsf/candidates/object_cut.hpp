#pragma once
// Step 3's cut of an object wider than a person in layer_objects() (layer_objects.hpp: split.depth_jump_mm,
// split.valley_cm, split.step_cm).
#include "rdsf/candidates/layer_shape.hpp"

namespace rdsf {

/// Height (cm, camera.height_cm(o.bottom - max(o.top, run.top) + 1, depth_mm_mean)) of the top of column c's
/// run above the object's lowest row; 0 when the run is empty or lies outside o.top..o.bottom.
double profile_cm(const LayerShape& shape, const LayerObject& o, int c);

/// The best place to cut o.fit_first..o.fit_last (the first column of the right piece), both pieces at least
/// min_piece wide, or -1. In order: the largest jump above split.depth_jump_mm between the column_depth_mm()
/// of neighbouring columns with a depth (empty columns skipped); else, where the deepest valley of
/// profile_cm() (min(running max from the left, from the right) - h) is at least split.valley_cm, middle_of()
/// the columns within 2 cm of that depth; else the largest step above split.step_cm between the mean heights
/// of columns_px(min_part_width_cm)-wide bands left and right of the cut. A criterion whose parameter is 0 is
/// skipped.
int cut_wide(const LayerShape& shape, const LayerObject& o, int min_piece);

}  // namespace rdsf
