#pragma once
// Joining in layer_objects() (layer_objects.hpp): a layer's passing columns into the thesis's objects
// (column_gap), and step 2, objects whose fitted extents touch into one (join_pieces).
#include <vector>

#include "rdsf/candidates/layer_shape.hpp"

namespace rdsf {

/// The thesis's objects, left to right: passing columns joined across gaps of at most column_gap columns
/// (a passing column `next` joins the group whose last passing column is `last` when next - last - 1 <=
/// column_gap); each group first..last becomes shape.span(first, last), not yet fitted. Invariants: the
/// objects do not overlap, more than column_gap columns that do not pass lie between neighbours, every
/// passing column is in one; none when no column passes.
std::vector<LayerObject> join_columns(const LayerShape& shape);

/// Step 2 (join_pieces), on fitted objects left to right: an object joins the one before it (which may
/// already be a join) when their fitted extents touch (o.fit_first <= previous.fit_last + 1) and together
/// they are at most max_person_width_cm wide (columns_cm(o.fit_last - previous.fit_first + 1)). When both are
/// narrower than min_width_cm (!wide_enough) they join only in a layer nearer than
/// join.narrow_layers_below_mm and, with join.narrow_passing, when passing_cm(previous) + passing_cm(o) >=
/// narrow.passing_width_cm (narrow_person.hpp). The joined object is span(previous.first, o.last) with the
/// fitted extent previous.fit_first..o.fit_last and fit_top the highest (smallest) of both fit_tops and its
/// top. Objects that join nothing are returned unchanged; the result is left to right.
std::vector<LayerObject> join_pieces(const LayerShape& shape, const std::vector<LayerObject>& objects);

}  // namespace rdsf
