#include "core/append_only_log.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <fcntl.h>
#include <unistd.h>

#include "core/error.hpp"

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
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) fail(path, std::string("cannot be opened for appending: ") + std::strerror(errno));
  const std::string text = line + "\n";
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = errno;
      ::close(fd);
      fail(path, std::string("append failed (disk full?): ") + std::strerror(error));
    }
    written += static_cast<std::size_t>(n);
  }
  const bool synced = ::fdatasync(fd) == 0;
  ::close(fd);
  if (!synced) fail(path, "cannot flush to disk");
}

void cut_torn_tail(const std::string& path, std::uint64_t size) {
  std::error_code ec;
  std::filesystem::resize_file(path, size, ec);
  if (ec) fail(path, "cannot cut off the torn end left by a killed writer: " + ec.message());
}

}  // namespace rdsf
