#include "rdsf/candidates/object_join.hpp"

#include <algorithm>

#include "rdsf/candidates/narrow_person.hpp"

namespace rdsf {

std::vector<LayerObject> join_columns(const LayerShape& shape) {
  const int width = shape.width(), column_gap = shape.params().column_gap;
  std::vector<LayerObject> found;
  int c = 0;
  while (c < width) {
    if (!shape.passes(c)) {
      ++c;
      continue;
    }
    int last = c;
    for (int next = c + 1; next < width && next - last - 1 <= column_gap; ++next) {
      if (shape.passes(next)) last = next;
    }
    found.push_back(shape.span(c, last));
    c = last + 1;
  }
  return found;
}

std::vector<LayerObject> join_pieces(const LayerShape& shape, const std::vector<LayerObject>& objects) {
  const CandidateParams& params = shape.params();
  const double depth_mm_mean = shape.layer().depth_mm_mean;
  std::vector<LayerObject> joined;
  for (const LayerObject& o : objects) {
    if (!joined.empty()) {
      LayerObject& previous = joined.back();
      // Pieces each too narrow to be a candidate alone join only in near layers (farther they are the
      // legs of furniture more often than a person's), with join.narrow_passing only when their passing
      // columns are together at least narrow.passing_width_cm wide (legs, not a chair's slats).
      const bool narrow = !shape.wide_enough(previous) && !shape.wide_enough(o);
      const bool touch =
          o.fit_first <= previous.fit_last + 1 &&
          (!narrow || (depth_mm_mean < params.join.narrow_layers_below_mm &&
                       (!params.join.narrow_passing ||
                        passing_cm(shape, previous) + passing_cm(shape, o) >= params.narrow.passing_width_cm)));
      if (touch && shape.columns_cm(o.fit_last - previous.fit_first + 1) <= params.max_person_width_cm) {
        const int fit_first = previous.fit_first, fit_top = std::min(previous.fit_top, o.fit_top);
        previous = shape.span(previous.first, o.last);
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

}  // namespace rdsf
