#include "rdsf/core/append_only_log.hpp"

#include <fstream>
#include <iterator>

#include "rdsf/core/durable_io.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {

LogLines read_log_lines(const std::string& path, const std::string& cannot_open) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, cannot_open);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  LogLines log;
  std::size_t position = 0;
  while (position < text.size()) {
    const std::size_t newline = text.find('\n', position);
    if (newline == std::string::npos) {
      log.torn_tail = true;
      break;
    }
    log.lines.push_back(text.substr(position, newline - position));
    position = newline + 1;
    log.complete_bytes = position;
  }
  return log;
}

void append_line_synced(const std::string& path, const std::string& line) {
  AppendFile file(path, /*create=*/true);
  file.append(line + "\n");
  file.close();
}

void cut_torn_tail(const std::string& path, std::uint64_t size) { cut_file_durably(path, size); }

}  // namespace rdsf
