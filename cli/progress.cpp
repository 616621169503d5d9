#include "cli/progress.hpp"

#include <cstdio>
#include <iostream>

#include <unistd.h>

namespace rdsf::cli {

Progress::Progress(std::ostream& out, std::string unit, std::optional<std::int64_t> total)
    : out_(out),
      unit_(std::move(unit)),
      total_(total),
      terminal_((&out == &std::cerr && isatty(2)) || (&out == &std::cout && isatty(1))),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

double Progress::elapsed_s() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::update(std::int64_t done, const std::string& extra) {
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_draw_).count();
  if (drawn_ && since < (terminal_ ? 0.2 : 5.0)) return;
  last_draw_ = now;
  draw(done, extra, false);
}

void Progress::finish(std::int64_t done, const std::string& extra) { draw(done, extra, true); }

void Progress::note(const std::string& line) {
  out_ << (terminal_ && drawn_ ? "\r\033[K" : "") << line << "\n";
  out_.flush();
  drawn_ = false;  // the next update draws the progress line again at once
}

void Progress::draw(std::int64_t done, const std::string& extra, bool final) {
  drawn_ = true;
  const double elapsed = elapsed_s();
  const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0.0;
  char line[256];
  int n = 0;
  if (total_ && *total_ > 0) {
    n = std::snprintf(line, sizeof line, "%s %lld/%lld (%3.0f%%)  %.1f %s/s", unit_.c_str(),
                      static_cast<long long>(done), static_cast<long long>(*total_),
                      100.0 * static_cast<double>(done) / static_cast<double>(*total_), rate, unit_.c_str());
    if (!final && rate > 0) {
      const double left = static_cast<double>(*total_ - done) / rate;
      n += std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), "  %.0f s left", left);
    }
  } else {
    n = std::snprintf(line, sizeof line, "%s %lld  %.1f %s/s", unit_.c_str(), static_cast<long long>(done), rate,
                      unit_.c_str());
  }
  if (final) std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), "  %.1f s", elapsed);
  out_ << (terminal_ ? "\r\033[K" : "") << line << (extra.empty() ? "" : "  ") << extra;
  if (final || !terminal_) out_ << "\n";
  out_.flush();
}

}  // namespace rdsf::cli
