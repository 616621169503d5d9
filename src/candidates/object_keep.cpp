#include "rdsf/candidates/object_keep.hpp"

#include "rdsf/candidates/narrow_person.hpp"

namespace rdsf {

bool keep_object(const LayerShape& shape, const LayerObject& o) {
  const CandidateParams& params = shape.params();
  if (!shape.wide_enough(o) && !narrow_person(shape, o)) return false;
  if (params.max_object_width_cm > 0 && shape.columns_cm(o.last - o.first + 1) > params.max_object_width_cm) {
    return false;
  }
  const bool at_border = o.fit_first == 0 || o.fit_last == shape.width() - 1;
  return at_border || shape.columns_cm(o.fit_last - o.fit_first + 1) >= params.min_fitted_width_cm;
}

}  // namespace rdsf
