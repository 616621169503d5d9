#pragma once
// A one-line progress display for long work: "frames 120/600 (20%)  41.3 fps  12 s left  <extra>".
// Redrawn in place on a terminal (at most 5 times a second), one line per report elsewhere (at most every
// 5 s), so logs stay short.
#include <chrono>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

namespace rdsf::cli {

class Progress {
 public:
  Progress(std::ostream& out, std::string unit, std::optional<std::int64_t> total);
  /// Reports that `done` units are finished; `extra` is appended ("candidates 312").
  void update(std::int64_t done, const std::string& extra = {});
  /// Prints the final line (always) and ends it with a newline.
  void finish(std::int64_t done, const std::string& extra = {});
  /// Prints `line` on a line of its own (above the progress line on a terminal, redrawn at the next update).
  void note(const std::string& line);
  double elapsed_s() const;

 private:
  void draw(std::int64_t done, const std::string& extra, bool final);
  std::ostream& out_;
  std::string unit_;
  std::optional<std::int64_t> total_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
  bool drawn_ = false;
};

}  // namespace rdsf::cli
