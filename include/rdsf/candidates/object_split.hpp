#pragma once
// Step 3 of layer_objects() (layer_objects.hpp): an object is cut between two heads (split_head.drop_cm,
// object_heads.hpp) or, wider than a person, where cut_wide() says (object_cut.hpp), and each piece again.
#include <vector>

#include "rdsf/candidates/layer_shape.hpp"

namespace rdsf {

/// depth_jump_mm, valley_cm or step_cm > 0: objects wider than a person may be cut.
bool split_wide_enabled(const WideSplitParams& split);

/// split_head.drop_cm > 0 and the layer's depth_mm_mean < split_head.layers_below_mm: objects of this layer
/// may be cut between heads.
bool split_heads_enabled(const LayerShape& shape);

/// The final pieces of an object, left to right, and whether its first cut was between heads.
struct ObjectPieces {
  std::vector<LayerObject> pieces;  ///< empty when the object is not cut
  bool by_heads = false;
};

/// The pieces of `whole`. With min_piece = max(1, columns_px(min_part_width_cm)), the cut column c (the first
/// of the right piece) is cut_between_heads() when split_heads_enabled(), else, with split_wide_enabled() and
/// columns_cm(whole.fit_last - whole.fit_first + 1) > max_person_width_cm, cut_wide(); none (-1): not cut.
/// Each side, fit_first..c - 1 and c..fit_last, becomes span() of its passing columns (none: no piece),
/// fitted by fit_object() within that side - within the whole's fitted extent after a cut between heads with
/// fit.across_head_cut - with part = true and object = whole.object; a piece narrower than min_width_cm
/// (!wide_enough) is dropped, the others are cut again (at most 5 cuts deep) and stand in the result by their
/// own pieces, or themselves when not cut.
ObjectPieces object_pieces(const LayerShape& shape, const LayerObject& whole);

/// Appends what `whole` becomes among the layer's objects: itself when object_pieces() finds none, else
/// its pieces, after itself when split_head.keep_whole (first cut between heads) or split.keep_whole
/// (otherwise) is set.
void split_object(const LayerShape& shape, const LayerObject& whole, std::vector<LayerObject>& out);

}  // namespace rdsf
