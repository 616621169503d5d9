#include "rdsf/dataset/sample_tsv.hpp"

#include <charconv>
#include <cmath>
#include <ctime>
#include <fstream>
#include <sstream>

#include "rdsf/core/append_only_log.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {

namespace {

constexpr int kColumns = 20;

std::string escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '\\': out += "\\\\"; break;
      case '\t': out += "\\t"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      default: out += c;
    }
  }
  return out;
}

std::string unescape(const std::string& text, const std::string& where, const char* column) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\\') {
      out += text[i];
      continue;
    }
    if (i + 1 >= text.size()) fail(where, std::string("column ") + column + ": dangling backslash");
    const char next = text[++i];
    switch (next) {
      case '\\': out += '\\'; break;
      case 't': out += '\t'; break;
      case 'n': out += '\n'; break;
      case 'r': out += '\r'; break;
      default: fail(where, std::string("column ") + column + ": unknown escape \\" + next);
    }
  }
  return out;
}

std::string format_double(double value) {
  char text[64];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

template <typename T>
T parse_integer(const std::string& field, const std::string& where, const char* column) {
  T value{};
  const auto result = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || result.ec != std::errc() || result.ptr != field.data() + field.size()) {
    fail(where, std::string("column ") + column + ": '" + field + "' is not an integer");
  }
  return value;
}

double parse_double(const std::string& field, const std::string& where, const char* column) {
  double value = 0;
  const auto result = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || result.ec != std::errc() || result.ptr != field.data() + field.size() ||
      !std::isfinite(value)) {
    fail(where, std::string("column ") + column + ": '" + field + "' is not a finite number");
  }
  return value;
}

bool parse_flag(const std::string& field, const std::string& where, const char* column) {
  if (field == "1") return true;
  if (field == "0") return false;
  fail(where, std::string("column ") + column + ": '" + field + "' must be 0 or 1");
}

bool is_hex16(const std::string& text) {
  if (text.size() != 16) return false;
  for (char c : text) {
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

}  // namespace

const std::string& sample_tsv_header() {
  static const std::string header =
      "id\tlabel\torigin\tsource\tframe\tstrict_x\tstrict_y\tstrict_w\tstrict_h\twindow_x\twindow_y\twindow_w\t"
      "window_h\tlayer_depth_mm\tmodel\tscore\ttime\thas_crop\thas_colour\tcrop_hash";
  return header;
}

std::string format_sample_row(const SampleRecord& r) {
  std::string row;
  row.reserve(160);
  auto add = [&row](const std::string& field) {
    if (!row.empty()) row += '\t';
    row += field;
  };
  row += std::to_string(r.id);
  add(std::to_string(r.label));
  add(escape(r.origin));
  add(escape(r.source));
  add(escape(r.frame));
  for (const cv::Rect& box : {r.strict_box, r.window}) {
    add(std::to_string(box.x));
    add(std::to_string(box.y));
    add(std::to_string(box.width));
    add(std::to_string(box.height));
  }
  add(format_double(r.layer_depth_mm));
  add(escape(r.model));
  add(r.score ? format_double(*r.score) : std::string());
  add(escape(r.time));
  add(r.has_crop ? "1" : "0");
  add(r.has_colour ? "1" : "0");
  add(r.crop_hash);
  return row;
}

SampleRecord parse_sample_row(const std::string& row, const std::string& where) {
  std::vector<std::string> f;
  f.reserve(kColumns);
  std::size_t start = 0;
  while (true) {
    const std::size_t tab = row.find('\t', start);
    f.push_back(row.substr(start, tab == std::string::npos ? std::string::npos : tab - start));
    if (tab == std::string::npos) break;
    start = tab + 1;
  }
  if (static_cast<int>(f.size()) != kColumns) {
    fail(where, std::to_string(f.size()) + " tab-separated columns, expected " + std::to_string(kColumns));
  }
  SampleRecord r;
  r.id = parse_integer<std::int64_t>(f[0], where, "id");
  if (r.id < 0) fail(where, "column id: negative id " + f[0]);
  if (f[1] != "0" && f[1] != "1") fail(where, "column label: '" + f[1] + "' must be 1 (person) or 0 (not)");
  r.label = f[1] == "1" ? 1 : 0;
  r.origin = unescape(f[2], where, "origin");
  r.source = unescape(f[3], where, "source");
  r.frame = unescape(f[4], where, "frame");
  static const char* const box_columns[8] = {"strict_x", "strict_y", "strict_w", "strict_h",
                                             "window_x", "window_y", "window_w", "window_h"};
  int box[8];
  for (int i = 0; i < 8; ++i) box[i] = parse_integer<int>(f[5 + static_cast<std::size_t>(i)], where, box_columns[i]);
  r.strict_box = cv::Rect(box[0], box[1], box[2], box[3]);
  r.window = cv::Rect(box[4], box[5], box[6], box[7]);
  if (box[2] < 0 || box[3] < 0 || box[6] < 0 || box[7] < 0) fail(where, "negative box width or height");
  r.layer_depth_mm = parse_double(f[13], where, "layer_depth_mm");
  r.model = unescape(f[14], where, "model");
  if (!f[15].empty()) r.score = parse_double(f[15], where, "score");
  r.time = unescape(f[16], where, "time");
  r.has_crop = parse_flag(f[17], where, "has_crop");
  r.has_colour = parse_flag(f[18], where, "has_colour");
  r.crop_hash = f[19];
  if (r.has_crop && !is_hex16(r.crop_hash)) {
    fail(where, "column crop_hash: '" + r.crop_hash + "' is not 16 lower-case hex digits");
  }
  if (!r.has_crop && (r.has_colour || !r.crop_hash.empty())) {
    fail(where, "a sample without crop (has_crop 0) cannot have a colour crop or a crop hash");
  }
  return r;
}

SampleTsvContents read_sample_tsv(const std::string& path) {
  const LogLines read = read_log_lines(path, "cannot be opened (is this a sample set folder?)");
  SampleTsvContents contents;
  contents.torn_tail = read.torn_tail;  // a row torn by a killed writer (or a header torn at creation)
  contents.complete_bytes = read.complete_bytes;
  for (std::size_t i = 0; i < read.lines.size(); ++i) {
    const std::string& line = read.lines[i];
    const std::size_t line_number = i + 1;
    const std::string where = path + ":" + std::to_string(line_number);
    if (line_number == 1) {
      if (line != sample_tsv_header()) {
        fail(where, "not a samples.tsv header (expected the columns listed in datasets/README.md)");
      }
    } else {
      SampleRecord record = parse_sample_row(line, where);
      if (!contents.records.empty() && record.id <= contents.records.back().id) {
        fail(where, "id " + std::to_string(record.id) + " does not follow id " +
                        std::to_string(contents.records.back().id) + " (ids must increase)");
      }
      contents.records.push_back(std::move(record));
    }
  }
  if (read.lines.empty()) {
    // Empty or torn header: a set whose creation was interrupted. Treat as holding no samples.
    contents.complete_bytes = 0;
  }
  return contents;
}

}  // namespace rdsf
