#include "rdsf/candidates/layer_objects.hpp"

#include "rdsf/candidates/layer_shape.hpp"
#include "rdsf/candidates/object_fit.hpp"
#include "rdsf/candidates/object_cut.hpp"
#include "rdsf/candidates/object_heads.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace rdsf {
namespace {

class ObjectShaper {
 public:
  ObjectShaper(const LayerView& layer, const CandidateParams& params)
      : shape_(layer, params), layer_(layer), params_(params), width_(shape_.width()) {}

  const std::vector<char>& passing() const { return shape_.passing(); }

  std::vector<LayerObject> objects() const {
    // The thesis: passing columns joined across gaps of at most column_gap columns.
    std::vector<LayerObject> found;
    int c = 0;
    while (c < width_) {
      if (!passes(c)) {
        ++c;
        continue;
      }
      int last = c;
      for (int next = c + 1; next < width_ && next - last - 1 <= params_.column_gap; ++next) {
        if (passes(next)) last = next;
      }
      found.push_back(span(c, last));
      c = last + 1;
    }
    for (LayerObject& o : found) fit(o, 0, width_ - 1);
    if (params_.join_pieces) found = join(found);
    std::vector<LayerObject> kept;
    int object = 0;
    for (LayerObject& o : found) {
      if (!wide_enough(o) && !narrow_person(o)) continue;
      if (params_.max_object_width_cm > 0 && cm(o.last - o.first + 1) > params_.max_object_width_cm) continue;
      const bool at_border = o.fit_first == 0 || o.fit_last == width_ - 1;  // a person cut by it looks narrow
      if (!at_border && cm(o.fit_last - o.fit_first + 1) < params_.min_fitted_width_cm) continue;
      std::vector<LayerObject> pieces;
      bool by_heads = false;
      o.object = object++;
      if (split_wide_enabled() || split_heads_enabled()) split(o, pieces, 0, &by_heads);
      if (pieces.empty() || (by_heads ? params_.split_head_keep_whole : params_.split_keep_whole)) kept.push_back(o);
      kept.insert(kept.end(), pieces.begin(), pieces.end());
    }
    return kept;
  }

 private:
  const ColumnRun& run(int c) const { return shape_.run(c); }
  bool passes(int c) const { return shape_.passes(c); }
  double cm(int pixels) const { return shape_.cm(pixels); }
  int px(double centimetres) const { return shape_.px(centimetres); }
  // Real width of the passing columns of o.first..o.last alone (the gaps between them left out).
  double passing_cm(const LayerObject& o) const {
    int n = 0;
    for (int x = o.first; x <= o.last; ++x) n += passes(x);
    return cm(n);
  }
  bool wide_enough(const LayerObject& o) const { return shape_.wide_enough(o); }
  // Step 4 (narrow_fitted_width_cm): an object too narrow over its passing columns that has a person's
  // fitted width, height, depth and a background above its top.
  bool narrow_person(const LayerObject& o) const {
    if (params_.narrow_fitted_width_cm <= 0) return false;
    if (cm(o.fit_last - o.fit_first + 1) < params_.narrow_fitted_width_cm) return false;
    if (cm(o.last - o.first + 1) < params_.narrow_passing_width_cm) return false;
    if (layer_.depth_mm_mean >= params_.narrow_layers_below_mm) return false;
    if (layer_.camera->height_cm(o.bottom - o.fit_top + 1, layer_.depth_mm_mean) < params_.narrow_min_height_cm) return false;
    return clear_above(o);
  }

  // Over the passing columns, at least half the pixels of the narrow_clear_above_cm band above the
  // object's top belong to other layers (rows above the image count as missing).
  bool clear_above(const LayerObject& o) const {
    const int band = std::max(1, px(params_.narrow_clear_above_cm));
    int other = 0, total = 0;
    for (int y = o.top - band; y < o.top; ++y) {
      const std::uint8_t* label = y >= 0 ? layer_.labels->ptr<std::uint8_t>(y) : nullptr;
      for (int x = o.first; x <= o.last; ++x, ++total) {
        if (label != nullptr && label[x] != 0 && label[x] != layer_.label) ++other;
      }
    }
    return total > 0 && 2 * other >= total;
  }

  bool split_wide_enabled() const {
    return params_.split_valley_cm > 0 || params_.split_depth_jump_mm > 0 || params_.split_step_cm > 0;
  }
  bool split_heads_enabled() const {
    return params_.split_head_drop_cm > 0 && layer_.depth_mm_mean < params_.split_head_layers_below_mm;
  }

  LayerObject span(int first, int last) const { return shape_.span(first, last); }
  // Step 1 (object_fit.hpp).
  void fit(LayerObject& o, int lo, int hi) const { fit_object(shape_, o, lo, hi); }

  // Step 2: neighbours whose fitted extents touch are one object when together no wider than a person.
  std::vector<LayerObject> join(const std::vector<LayerObject>& objects) const {
    std::vector<LayerObject> joined;
    for (const LayerObject& o : objects) {
      if (!joined.empty()) {
        LayerObject& previous = joined.back();
        // Pieces each too narrow to be a candidate alone join only in near layers (farther they are the
        // legs of furniture more often than a person's), with join_narrow_passing only when their passing
        // columns are together at least narrow_passing_width_cm wide (legs, not a chair's slats).
        const bool narrow = !wide_enough(previous) && !wide_enough(o);
        const bool touch = o.fit_first <= previous.fit_last + 1 &&
                           (!narrow || (layer_.depth_mm_mean < params_.join_narrow_layers_below_mm &&
                                        (!params_.join_narrow_passing || passing_cm(previous) + passing_cm(o) >= params_.narrow_passing_width_cm)));
        if (touch && cm(o.fit_last - previous.fit_first + 1) <= params_.max_person_width_cm) {
          const int fit_first = previous.fit_first, fit_top = std::min(previous.fit_top, o.fit_top);
          previous = span(previous.first, o.last);
          previous.fit_first = fit_first;
          previous.fit_last = o.fit_last;
          previous.fit_top = std::min(fit_top, previous.top);
          continue;
        }
      }
      joined.push_back(o);
    }
    return joined;
  }

  // Step 3: an object with two heads (split_head_drop_cm) is cut between them, else one wider than a person
  // where cut_wide() (object_cut.hpp) says, and each piece again; the final pieces (with their passing columns) are appended to
  // `out`, nothing when the object is not cut. *by_heads tells whether the first cut was between heads.
  void split(const LayerObject& whole, std::vector<LayerObject>& out, int depth = 0, bool* by_heads = nullptr) const {
    if (depth > 4) return;
    const int min_piece = std::max(1, px(params_.min_part_width_cm));
    int c = split_heads_enabled() ? cut_between_heads(shape_, whole, min_piece) : -1;
    const bool heads = c >= 0;
    if (by_heads != nullptr) *by_heads = heads;
    if (c < 0 && split_wide_enabled() && cm(whole.fit_last - whole.fit_first + 1) > params_.max_person_width_cm) {
      c = cut_wide(shape_, whole, min_piece);
    }
    if (c < 0) return;
    for (const auto& [lo, hi] : {std::pair<int, int>{whole.fit_first, c - 1}, std::pair<int, int>{c, whole.fit_last}}) {
      int first = -1, last = -1;
      for (int x = lo; x <= hi; ++x) {
        if (!passes(x)) continue;
        if (first < 0) first = x;
        last = x;
      }
      if (first < 0) continue;
      LayerObject piece = span(first, last);
      // Between heads the columns around the cut may hold an arm either person holds out: with
      // fit_across_head_cut each piece reaches over them up to the other piece's passing columns.
      if (heads && params_.fit_across_head_cut) {
        fit(piece, whole.fit_first, whole.fit_last);
      } else {
        fit(piece, lo, hi);
      }
      piece.part = true;
      piece.object = whole.object;
      if (!wide_enough(piece)) continue;
      const std::size_t before = out.size();
      split(piece, out, depth + 1);
      if (out.size() == before) out.push_back(piece);
    }
  }

  LayerShape shape_;
  const LayerView& layer_;
  const CandidateParams& params_;
  const int width_;
};

}  // namespace

LayerObjects layer_objects(const LayerView& layer, const CandidateParams& params) {
  ObjectShaper shaper(layer, params);
  return {shaper.objects(), shaper.passing()};
}

}  // namespace rdsf
