#include "dataset/retraction_log.hpp"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

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
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be opened");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::size_t position = 0;
  std::int64_t line_number = 0;
  while (position < text.size()) {
    const std::size_t newline = text.find('\n', position);
    ++line_number;
    if (newline == std::string::npos) {
      log.torn_tail = true;
      break;
    }
    const std::string line = text.substr(position, newline - position);
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
    position = newline + 1;
    log.complete_bytes = position;
  }
  return log;
}

}  // namespace rdsf
