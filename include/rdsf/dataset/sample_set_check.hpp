#pragma once
// Checking a sample set for every problem (rdsf-samples --check) and repairing what can be repaired
// (rdsf-samples --repair). Problems and their repairs:
//   torn last row of samples.tsv            cut off (never reported as saved)
//   unparseable row, duplicate or           dropped from the index (the backup keeps it)
//   non-increasing id
//   depth crop missing, empty, truncated,   the sample is retracted with the reason (retracted.tsv); its
//   wrong size or type, not its crop_hash   row and files stay for inspection
//   colour crop unusable                    reported only (the depth crop, the sample, is valid)
//   temporary file or crop without a row    removed
//   manifest unreadable or its feature      reported only: nothing is changed in a set without a valid
//   spec hash does not match                manifest
// A repair first copies samples.tsv (and retracted.tsv) to <name>.bak-<UTC time>, holds the set's lock,
// and writes through core/durable_io.
#include <cstdint>
#include <string>
#include <vector>

#include "rdsf/dataset/sample_record.hpp"
#include "rdsf/features/feature_spec.hpp"

namespace rdsf {

/// Why the depth crop at `path` of `record` is unusable, or "" when it is fine. `full`: decoded, its size,
/// type and hash checked; otherwise only its presence and size are looked at.
std::string depth_crop_problem(const std::string& path, const SampleRecord& record, const FeatureSpec& spec,
                               bool full);

struct SetProblem {
  std::string where;  ///< the file (relative to the set), with ":line" for index rows
  std::string what;   ///< the problem, naming the sample when there is one
  std::string fix;    ///< what --repair does; empty when it cannot be repaired
};

/// Every problem of the set in `dir` (crops decoded and hashed).
std::vector<SetProblem> check_sample_set(const std::string& dir);

/// Repairs what check_sample_set() finds and can be repaired; returns one line per change.
std::vector<std::string> repair_sample_set(const std::string& dir);

}  // namespace rdsf
