#pragma once
// The one rule for a sample's `source` (the samples.tsv column, datasets/README.md), used by every program
// that appends samples cut from frames, so that the column and de-duplication (which compares it) do not
// depend on the program or on the working folder:
//   - a file or folder (a PNG folder, a list file, an .oni recording): its absolute path, lexically
//     normalised, symbolic links resolved, without a trailing '/' ("./data//empty/" run in /lab ->
//     "/lab/data/empty");
//   - anything else (a device: "openni", an OpenNI URI such as "rdsf-png:///frames"): as given.
// Validation groups take only the last path component (sample_groups.hpp), so sets written before this
// rule (relative sources) still group with new rows of the same recording.
#include <string>

namespace rdsf {

std::string sample_source(const std::string& spec);

}  // namespace rdsf
