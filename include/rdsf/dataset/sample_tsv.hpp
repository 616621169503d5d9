#pragma once
// The text form of samples.tsv, the append-only index of a sample set: a header line, then one
// tab-separated row per sample, each ending in a newline. A last line without its newline is a row torn by
// a killed writer: readers ignore it, writers cut it off. Every other row is checked strictly (column
// count, numbers, values) and the first bad one is named by file and line.
#include <cstdint>
#include <string>
#include <vector>

#include "rdsf/dataset/sample_record.hpp"

namespace rdsf {

/// The header line, without its newline.
const std::string& sample_tsv_header();

/// One row, without its newline. Text fields are escaped (\\ \t \n \r).
std::string format_sample_row(const SampleRecord& record);

/// Parses one row (without newline); throws Error "<where>: ..." naming the bad column.
SampleRecord parse_sample_row(const std::string& row, const std::string& where);

struct SampleTsvContents {
  std::vector<SampleRecord> records;
  /// Bytes of the file that hold the header and complete rows; a torn last row starts here.
  std::uint64_t complete_bytes = 0;
  /// True when the file ended in a torn (newline-less) row, ignored.
  bool torn_tail = false;
};

/// Reads samples.tsv. Throws Error naming the file and line of the first bad row, a wrong header, ids not
/// strictly increasing, or a missing file.
SampleTsvContents read_sample_tsv(const std::string& path);

}  // namespace rdsf
