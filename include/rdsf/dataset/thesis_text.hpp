#pragma once
// The thesis's text format for exchanging samples with other tools: one sample a line,
//   label f1 f2 ... fN
// label 1 (person) or 0 (not), then the N = 8128 feature values (each in [0, 1]) separated by spaces or
// tabs. Blank lines are ignored.
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/features/rdsf_extractor.hpp"

namespace rdsf {

struct ThesisImportResult {
  std::int64_t lines = 0;       ///< sample lines in the file
  std::int64_t imported = 0;    ///< appended to the set
  std::int64_t duplicates = 0;  ///< skipped: the same line of the same file was imported before
};

/// Checks every line of `path` first (label 1 or 0, exactly the set's dimension of numbers, each finite and
/// in [0, 1]) and throws Error "<path>:<line>: <problem>" naming the first bad line, importing nothing.
/// Then appends each line as a sample without crop (origin "import", source `path`, frame "line N",
/// has_crop false) whose feature vector is stored in the set.
/// `already_checked`: check_thesis_text() has passed on the file (its check is then not repeated).
ThesisImportResult import_thesis_text(const std::string& path, SampleSetWriter& writer, bool already_checked = false);

/// Checks every line as import_thesis_text() does, for `dimension` values a line; returns the number of
/// samples. Throws Error "<path>:<line>: <problem>".
std::int64_t check_thesis_text(const std::string& path, int dimension);

/// The one writer of the format: appends one line per row of `rows` (label from `labels`, then the row's
/// values with the shortest text that reads back as the same float) to `out`.
void write_thesis_lines(std::ostream& out, const cv::Mat1f& rows, const std::vector<int>& labels);

/// Writes `rows` and their `labels` to `path` through a temporary file; refuses to replace an existing
/// file unless `overwrite`. Returns the number of lines. (rdsf-train --export-text: a recipe's samples.)
std::int64_t write_thesis_text(const cv::Mat1f& rows, const std::vector<int>& labels, const std::string& path,
                               bool overwrite);

/// Writes every record of `set` (features from `extractor`) to `path` as write_thesis_text() does, in
/// chunks (rdsf-samples --export: a whole set). Returns the number of lines.
std::int64_t export_thesis_text(const SampleSet& set, const RdsfExtractor& extractor, const std::string& path,
                                bool overwrite);

}  // namespace rdsf
