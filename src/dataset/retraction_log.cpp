#include "rdsf/dataset/retraction_log.hpp"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "rdsf/core/append_only_log.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {

const std::string& retraction_log_header() {
  static const std::string header = "id\ttime";
  return header;
}

RetractionLog read_retraction_log(const std::string& path) {
  RetractionLog log;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return log;
  log.exists = true;
  const LogLines read = read_log_lines(path);
  log.torn_tail = read.torn_tail;
  log.complete_bytes = read.complete_bytes;
  for (std::size_t i = 0; i < read.lines.size(); ++i) {
    const std::string& line = read.lines[i];
    const std::size_t line_number = i + 1;
    const std::string where = path + ":" + std::to_string(line_number);
    if (line_number == 1) {
      if (line != retraction_log_header()) fail(where, "not a retracted.tsv header (expected 'id<TAB>time')");
    } else {
      const std::size_t tab = line.find('\t');
      std::int64_t id = -1;
      const auto result = std::from_chars(line.data(), line.data() + (tab == std::string::npos ? line.size() : tab), id);
      if (tab == std::string::npos || result.ec != std::errc() || result.ptr != line.data() + tab || id < 0) {
        fail(where, "expected 'id<TAB>time' with a sample id");
      }
      log.ids.insert(id);
    }
  }
  return log;
}

}  // namespace rdsf
