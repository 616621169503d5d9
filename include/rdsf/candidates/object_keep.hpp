#pragma once
// Which of a layer's joined objects layer_objects() (layer_objects.hpp) keeps, before splitting them: wide
// enough or a narrow person (step 4), not a wall (max_object_width_cm), not a post (min_fitted_width_cm).
#include "rdsf/candidates/layer_shape.hpp"

namespace rdsf {

/// True when all hold: wide_enough(o) (columns_cm(o.last - o.first + 1) >= min_width_cm) or narrow_person(o)
/// (narrow_person.hpp); with max_object_width_cm > 0, columns_cm(o.last - o.first + 1) <=
/// max_object_width_cm; and columns_cm(o.fit_last - o.fit_first + 1) >= min_fitted_width_cm unless the fitted
/// extent touches the image's left or right border (fit_first == 0 or fit_last == width - 1: a person cut by
/// it looks narrow).
bool keep_object(const LayerShape& shape, const LayerObject& o);

}  // namespace rdsf
