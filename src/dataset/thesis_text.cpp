#include "rdsf/dataset/thesis_text.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <vector>

#include "rdsf/core/atomic_file.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// Parses one line into label and values; returns false for a blank line. Throws Error naming `where`.
bool parse_line(const std::string& line, int dimension, const std::string& where, int& label,
                std::vector<float>& values) {
  const char* p = line.data();
  const char* const end = p + line.size();
  auto skip = [&] {
    while (p < end && is_space(*p)) ++p;
  };
  auto token_end = [&] {
    const char* q = p;
    while (q < end && !is_space(*q)) ++q;
    return q;
  };
  skip();
  if (p == end) return false;
  const char* q = token_end();
  const std::string label_text(p, q);
  if (label_text != "1" && label_text != "0") {
    fail(where, "label '" + label_text + "' must be 1 (person) or 0 (not)");
  }
  label = label_text == "1" ? 1 : 0;
  p = q;
  values.clear();
  while (true) {
    skip();
    if (p == end) break;
    q = token_end();
    const int column = static_cast<int>(values.size()) + 1;
    if (column > dimension) {
      fail(where, "more than " + std::to_string(dimension) + " feature values (expected label f1 ... f" +
                      std::to_string(dimension) + ")");
    }
    float value = 0;
    const auto result = std::from_chars(p, q, value);
    if (result.ec != std::errc() || result.ptr != q || !std::isfinite(value)) {
      fail(where, "value f" + std::to_string(column) + " '" + std::string(p, q) + "' is not a finite number");
    }
    // Bhattacharyya coefficients lie in [0, 1]; allow float rounding just above 1.
    if (value < 0.0f || value > 1.0f + 1e-4f) {
      fail(where, "value f" + std::to_string(column) + " = " + std::string(p, q) + " is outside [0, 1]");
    }
    values.push_back(value);
    p = q;
  }
  if (static_cast<int>(values.size()) != dimension) {
    fail(where, std::to_string(values.size()) + " feature values, expected " + std::to_string(dimension));
  }
  return true;
}

// Calls fn(line number, label, values) for every sample line of `path`, checked as parse_line() does.
template <typename Fn>
void for_each_sample_line(const std::string& path, int dimension, Fn&& fn) {
  std::vector<float> values;
  values.reserve(static_cast<std::size_t>(dimension));
  int label = 0;
  std::ifstream in(path);
  if (!in) fail(path, "cannot be opened");
  std::string line;
  std::int64_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (parse_line(line, dimension, path + ":" + std::to_string(number), label, values)) fn(number, label, values);
  }
  if (in.bad()) fail(path, "read failed");
}

}  // namespace

std::int64_t check_thesis_text(const std::string& path, int dimension) {
  std::int64_t lines = 0;
  for_each_sample_line(path, dimension, [&](std::int64_t, int, const std::vector<float>&) { ++lines; });
  if (lines == 0) fail(path, "holds no samples");
  return lines;
}

ThesisImportResult import_thesis_text(const std::string& path, SampleSetWriter& writer, bool already_checked) {
  ThesisImportResult result;
  // Pass 1: check every line, import nothing when one is bad.
  if (!already_checked) check_thesis_text(path, writer.dimension());
  // Pass 2: append.
  for_each_sample_line(path, writer.dimension(), [&](std::int64_t number, int label, const std::vector<float>& values) {
    ++result.lines;
    SampleRecord record;
    record.label = label;
    record.origin = "import";
    record.source = path;
    record.frame = "line " + std::to_string(number);
    record.has_crop = false;
    if (writer.is_duplicate(record)) {
      ++result.duplicates;
      return;
    }
    writer.append_vector(record, values.data());
    ++result.imported;
  });
  return result;
}

void write_thesis_lines(std::ostream& out, const cv::Mat1f& rows, const std::vector<int>& labels) {
  if (rows.rows != static_cast<int>(labels.size())) throw Error("thesis text: rows and labels differ in number");
  std::string line;
  char text[32];
  for (int r = 0; r < rows.rows; ++r) {
    line.assign(labels[static_cast<std::size_t>(r)] == 1 ? "1" : "0");
    const float* row = rows.ptr<float>(r);
    for (int c = 0; c < rows.cols; ++c) {
      const auto written = std::to_chars(text, text + sizeof text, row[c]);
      line.push_back(' ');
      line.append(text, written.ptr);
    }
    line.push_back('\n');
    out << line;
  }
}

std::int64_t write_thesis_text(const cv::Mat1f& rows, const std::vector<int>& labels, const std::string& path,
                               bool overwrite) {
  AtomicTextFile file(path, overwrite);
  write_thesis_lines(file.stream(), rows, labels);
  file.commit();
  return rows.rows;
}

std::int64_t export_thesis_text(const SampleSet& set, const RdsfExtractor& extractor, const std::string& path,
                                bool overwrite) {
  AtomicTextFile file(path, overwrite);
  const std::size_t total = set.records().size();
  constexpr std::size_t kChunk = 2048;
  for (std::size_t begin = 0; begin < total; begin += kChunk) {
    std::vector<std::size_t> indices;
    std::vector<int> labels;
    for (std::size_t i = begin; i < std::min(total, begin + kChunk); ++i) {
      indices.push_back(i);
      labels.push_back(set.records()[i].label);
    }
    write_thesis_lines(file.stream(), set.features(extractor, indices), labels);
    file.flush();
  }
  file.commit();
  return static_cast<std::int64_t>(total);
}

}  // namespace rdsf
