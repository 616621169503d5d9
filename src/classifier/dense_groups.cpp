#include "rdsf/classifier/dense_groups.hpp"

#include <algorithm>

namespace rdsf {

DenseGroups dense_groups(const std::vector<std::size_t>& group_ids) {
  std::vector<std::size_t> ids = group_ids;
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  DenseGroups out;
  out.count = ids.size();
  out.of_row.reserve(group_ids.size());
  for (std::size_t id : group_ids) {
    out.of_row.push_back(static_cast<std::size_t>(std::lower_bound(ids.begin(), ids.end(), id) - ids.begin()));
  }
  return out;
}

}  // namespace rdsf
