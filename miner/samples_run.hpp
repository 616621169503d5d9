#pragma once
// rdsf-samples' work: describe a sample set, import or export the thesis's text format.
#include <string>

namespace rdsf {

struct SamplesOptions {
  std::string set;          ///< the sample set folder
  std::string import_file;  ///< thesis text file to import into the set (created when absent)
  std::string export_file;  ///< thesis text file to write from the set
  bool force = false;       ///< replace an existing export file
};

/// Returns the process exit code.
int run_samples(const SamplesOptions& options);

}  // namespace rdsf
