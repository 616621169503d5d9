#include "rdsf/candidates/object_split.hpp"

#include <algorithm>
#include <utility>

#include "rdsf/candidates/object_cut.hpp"
#include "rdsf/candidates/object_fit.hpp"
#include "rdsf/candidates/object_heads.hpp"

namespace rdsf {
namespace {

// Appends the final pieces of `whole` to `out` (nothing when it is not cut); *by_heads tells whether the
// cut was between heads.
void cut_into_pieces(const LayerShape& shape, const LayerObject& whole, std::vector<LayerObject>& out, int depth,
                     bool* by_heads) {
  if (depth > 4) return;
  const CandidateParams& params = shape.params();
  const int min_piece = std::max(1, shape.columns_px(params.min_part_width_cm));
  int c = split_heads_enabled(shape) ? cut_between_heads(shape, whole, min_piece) : -1;
  const bool heads = c >= 0;
  if (by_heads != nullptr) *by_heads = heads;
  if (c < 0 && split_wide_enabled(params.split) &&
      shape.columns_cm(whole.fit_last - whole.fit_first + 1) > params.max_person_width_cm) {
    c = cut_wide(shape, whole, min_piece);
  }
  if (c < 0) return;
  for (const auto& [lo, hi] : {std::pair<int, int>{whole.fit_first, c - 1}, std::pair<int, int>{c, whole.fit_last}}) {
    int first = -1, last = -1;
    for (int x = lo; x <= hi; ++x) {
      if (!shape.passes(x)) continue;
      if (first < 0) first = x;
      last = x;
    }
    if (first < 0) continue;
    LayerObject piece = shape.span(first, last);
    // Between heads the columns around the cut may hold an arm either person holds out: with
    // fit.across_head_cut each piece reaches over them up to the other piece's passing columns.
    if (heads && params.fit.across_head_cut) {
      fit_object(shape, piece, whole.fit_first, whole.fit_last);
    } else {
      fit_object(shape, piece, lo, hi);
    }
    piece.part = true;
    piece.object = whole.object;
    if (!shape.wide_enough(piece)) continue;
    const std::size_t before = out.size();
    cut_into_pieces(shape, piece, out, depth + 1, nullptr);
    if (out.size() == before) out.push_back(piece);
  }
}

}  // namespace

bool split_wide_enabled(const WideSplitParams& split) {
  return split.valley_cm > 0 || split.depth_jump_mm > 0 || split.step_cm > 0;
}

bool split_heads_enabled(const LayerShape& shape) {
  const HeadSplitParams& heads = shape.params().split_head;
  return heads.drop_cm > 0 && shape.layer().depth_mm_mean < heads.layers_below_mm;
}

ObjectPieces object_pieces(const LayerShape& shape, const LayerObject& whole) {
  ObjectPieces found;
  if (split_wide_enabled(shape.params().split) || split_heads_enabled(shape)) {
    cut_into_pieces(shape, whole, found.pieces, 0, &found.by_heads);
  }
  return found;
}

void split_object(const LayerShape& shape, const LayerObject& whole, std::vector<LayerObject>& out) {
  const CandidateParams& params = shape.params();
  const ObjectPieces found = object_pieces(shape, whole);
  if (found.pieces.empty() || (found.by_heads ? params.split_head.keep_whole : params.split.keep_whole)) {
    out.push_back(whole);
  }
  out.insert(out.end(), found.pieces.begin(), found.pieces.end());
}

}  // namespace rdsf
