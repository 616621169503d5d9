#pragma once
// rdsf-samples' work: describe a sample set, import or export the thesis's text format.
#include <string>

namespace rdsf {

struct SamplesOptions {
  std::string set;          ///< the sample set folder
  std::string import_file;  ///< thesis text file to import into the set (created when absent)
  std::string export_file;  ///< thesis text file to write from the set
  bool force = false;       ///< replace an existing export file
  bool check = false;       ///< list every problem of the set (exit 1 when there is one)
  bool repair = false;      ///< repair what can be repaired, after a backup of the index
};

/// Returns the process exit code.
int run_samples(const SamplesOptions& options);

}  // namespace rdsf
