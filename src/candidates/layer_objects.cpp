#include "rdsf/candidates/layer_objects.hpp"

#include "rdsf/candidates/layer_shape.hpp"
#include "rdsf/candidates/object_fit.hpp"
#include "rdsf/candidates/object_join.hpp"
#include "rdsf/candidates/object_keep.hpp"
#include "rdsf/candidates/object_split.hpp"

namespace rdsf {

LayerObjects layer_objects(const LayerView& layer, const CandidateParams& params) {
  const LayerShape shape(layer, params);
  std::vector<LayerObject> found = join_columns(shape);                     // the thesis's objects
  for (LayerObject& o : found) fit_object(shape, o, 0, shape.width() - 1);  // 1. fitted extent
  if (params.join.pieces) found = join_pieces(shape, found);               // 2. joining pieces
  LayerObjects objects{{}, shape.passing()};
  int object = 0;
  for (LayerObject& o : found) {
    if (!keep_object(shape, o)) continue;  // 4. narrow people stay; walls and posts go
    o.object = object++;
    split_object(shape, o, objects.objects);  // 3. splitting: the object, its pieces or both
  }
  return objects;
}

}  // namespace rdsf
