#pragma once
// Group ids (any numbers, e.g. hashes of recording and frame block) renumbered 0..count-1 in ascending
// order of the ids: the one place the validation code turns a row's group into an index (group split,
// group folds, the validation source text).
#include <cstddef>
#include <vector>

namespace rdsf {

struct DenseGroups {
  std::size_t count = 0;                ///< distinct ids
  std::vector<std::size_t> of_row;      ///< per row: the rank of its id among the distinct ids
};

DenseGroups dense_groups(const std::vector<std::size_t>& group_ids);

}  // namespace rdsf
