#pragma once
// retracted.tsv in a sample set: the samples taken back after they were appended (the labeler's undo).
// The index samples.tsv stays append-only; a retracted sample's row stays in it, and its crops stay on
// disk for inspection, but readers leave it out. Format: a header line "id<TAB>time", then one row per
// retraction, each ending in a newline; a torn last row (killed writer) is ignored by readers and cut off
// by the next writer.
#include <cstdint>
#include <string>
#include <unordered_set>

namespace rdsf {

const std::string& retraction_log_header();

struct RetractionLog {
  std::unordered_set<std::int64_t> ids;
  std::uint64_t complete_bytes = 0;  ///< bytes of the header and complete rows
  bool torn_tail = false;
  bool exists = false;
};

/// Reads the log; a missing file retracts nothing. Throws Error naming the file and line of a bad row.
RetractionLog read_retraction_log(const std::string& path);

}  // namespace rdsf
