#include "features/feature_spec.hpp"

#include "core/error.hpp"
#include "core/stable_hash.hpp"

namespace rdsf {

void FeatureSpec::pair_at(int index, int& i, int& j) const {
  const int n = cell_count();
  i = 0;
  int row_length = n - 1;
  while (index >= row_length) {
    index -= row_length;
    ++i;
    --row_length;
  }
  j = i + 1 + index;
}

std::string FeatureSpec::canonical() const {
  return "rdsf/1 window=" + std::to_string(window_width_px) + "x" + std::to_string(window_height_px) +
         " cell=" + std::to_string(cell_px) + " bins=nodata+" + std::to_string(bin_count() - 1) + "x" +
         std::to_string(bin_width_mm) + "mm clamp=" + std::to_string(max_depth_mm) +
         "mm pairs=upper-row-major crop=nearest-masked";
}

std::string FeatureSpec::hash() const { return to_hex16(fnv1a64(canonical())); }

void FeatureSpec::validate() const {
  if (cell_px <= 0 || window_width_px <= 0 || window_height_px <= 0 || window_width_px % cell_px != 0 ||
      window_height_px % cell_px != 0) {
    throw Error("feature spec: cells of " + std::to_string(cell_px) + " px must tile the " +
                std::to_string(window_width_px) + "x" + std::to_string(window_height_px) + " window");
  }
  if (cell_count() < 2) throw Error("feature spec: at least two cells are needed");
  if (bin_width_mm <= 0 || max_depth_mm < bin_width_mm || max_depth_mm % bin_width_mm != 0) {
    throw Error("feature spec: max depth must be a positive multiple of the bin width");
  }
}

}  // namespace rdsf
