#pragma once
// Append-only text logs (samples.tsv, retracted.tsv, labeler-answers.tsv): one record a line, each line
// appended in one write and synced to disk before the program moves on. A writer killed mid-append leaves
// at most one torn last line (no '\n'), which readers ignore and writers cut off.
#include <cstdint>
#include <string>
#include <vector>

namespace rdsf {

struct LogLines {
  std::vector<std::string> lines;    ///< the complete lines, without their '\n'
  bool torn_tail = false;            ///< the file ends in a line without '\n' (ignored)
  std::uint64_t complete_bytes = 0;  ///< bytes up to the end of the last complete line
};

/// Reads `path`; throws Error("<path>: <cannot_open>") when it cannot be opened.
LogLines read_log_lines(const std::string& path, const std::string& cannot_open = "cannot be opened");

/// Appends `line` and '\n' in one write with O_APPEND and syncs it to disk (fdatasync; a file it creates is
/// fsync'ed in its folder), through core/durable_io; throws Error naming `path` and the cause on failure.
void append_line_synced(const std::string& path, const std::string& line);

/// Cuts `path` to `size` bytes (the torn tail a killed writer left) and syncs it; throws Error naming `path`.
void cut_torn_tail(const std::string& path, std::uint64_t size);

}  // namespace rdsf
