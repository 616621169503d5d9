#pragma once
// Joins sample sets (e.g. the shards of a cluster job array) into one: every sample of every input is
// appended to the output in input order (new ids), crops and stored vectors copied, exact duplicates
// skipped. All inputs must have the output's feature spec.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "rdsf/dataset/sample_set_writer.hpp"

namespace rdsf {

struct MergeResult {
  std::int64_t inputs = 0;
  std::int64_t added = 0;
  std::int64_t duplicates = 0;  ///< already in the output (SampleSetWriter::is_duplicate)
};

/// Checks every input's manifest first (feature spec equal to the output's; throws Error naming the input
/// and both hashes otherwise), then copies the samples `keep` takes (every sample when it is empty;
/// rdsf-adapt's held-out check keeps those of the earlier frames).
MergeResult merge_sample_sets(const std::vector<std::string>& input_dirs, SampleSetWriter& out,
                              const std::function<bool(const SampleRecord&)>& keep = {});

}  // namespace rdsf
