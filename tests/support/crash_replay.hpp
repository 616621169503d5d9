#pragma once
// The power-cut simulation: reads the record of file calls a program made through core/durable_io
// (RDSF_IO_RECORD=FILE), replays its first k calls on a model of a file system, and writes out what a disk
// would hold after a power cut at that point:
//   Loss::unsynced   the pessimistic cut: only data fdatasync'ed and names whose folder was fsync'ed
//                    survive (a name whose folder was not synced is lost, with everything below it);
//   Loss::data_only  every name survives (the journal of the file system reached the disk) but file data
//                    only as far as it was synced: the "renamed, empty file" of ext4 delayed allocation.
// Files are modelled as inodes with a live and a synced copy of their bytes; folders as the names in them,
// live and synced.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "rdsf/core/durable_io.hpp"

namespace rdsf::test {

struct RecordedCall {
  io::Call call;
  int fd = -1;
  std::int64_t value = 0;  ///< open: flags; write: offset; truncate: size
  std::string path, path2, data;
};

/// Reads a record file; throws rdsf::Error on a malformed one.
std::vector<RecordedCall> read_io_record(const std::string& path);

enum class Loss { unsynced, data_only };

/// Writes what survives a power cut after the first `cut` calls, for the files under `root` (the folder
/// the program wrote into, assumed synced before it started), into the empty folder `out` (root's
/// contents become out's). Returns the number of files written.
std::size_t materialize_after_cut(const std::vector<RecordedCall>& calls, std::size_t cut, const std::string& root,
                                  Loss loss, const std::string& out);

}  // namespace rdsf::test
