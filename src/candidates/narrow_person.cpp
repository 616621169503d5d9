#include "rdsf/candidates/narrow_person.hpp"

#include <algorithm>
#include <cstdint>

namespace rdsf {

double passing_cm(const LayerShape& shape, const LayerObject& o) {
  int n = 0;
  for (int x = o.first; x <= o.last; ++x) n += shape.passes(x);
  return shape.columns_cm(n);
}

bool clear_above(const LayerShape& shape, const LayerObject& o) {
  const LayerView& layer = shape.layer();
  const int band = std::max(1, shape.rows_px(shape.params().narrow.clear_above_cm));
  int other = 0, total = 0;
  for (int y = o.top - band; y < o.top; ++y) {
    const std::uint8_t* label = y >= 0 ? layer.labels->ptr<std::uint8_t>(y) : nullptr;
    for (int x = o.first; x <= o.last; ++x, ++total) {
      if (label != nullptr && label[x] != 0 && label[x] != layer.label) ++other;
    }
  }
  return total > 0 && 2 * other >= total;
}

bool narrow_person(const LayerShape& shape, const LayerObject& o) {
  const NarrowPersonParams& narrow = shape.params().narrow;
  const LayerView& layer = shape.layer();
  if (narrow.fitted_width_cm <= 0) return false;
  if (shape.columns_cm(o.fit_last - o.fit_first + 1) < narrow.fitted_width_cm) return false;
  if (shape.columns_cm(o.last - o.first + 1) < narrow.passing_width_cm) return false;
  if (layer.depth_mm_mean >= narrow.layers_below_mm) return false;
  if (layer.camera->height_cm(o.bottom - o.fit_top + 1, layer.depth_mm_mean) < narrow.min_height_cm) return false;
  return clear_above(shape, o);
}

}  // namespace rdsf
