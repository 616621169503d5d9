#pragma once
// Shared helpers for the tests: the real frames beside the project, temporary folders, and running the
// programs as a user would (exit code and output captured).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/synth/synth_params.hpp"

namespace rdsf::test {

/// ../shared/realdata beside the project root; empty path when absent (tests then GTEST_SKIP()).
std::filesystem::path realdata_dir();

/// Skips the current test with a message when ../shared/realdata is absent. Use at the top of a TEST.
#define RDSF_REQUIRE_REALDATA()                                                              \
  do {                                                                                       \
    if (::rdsf::test::realdata_dir().empty())                                                \
      GTEST_SKIP() << "../shared/realdata is absent: real-frame test skipped";               \
  } while (0)

/// A fresh empty folder under the system temp folder, removed when the object dies.
class TempDir {
 public:
  explicit TempDir(const std::string& tag = "rdsf-test");
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

/// Path of a built program ("rdsf-detect" -> <build>/detector/rdsf-detect).
std::string program(const std::string& name);

struct RunResult {
  int exit_code = -1;
  std::string out;  ///< standard output
  std::string err;  ///< standard error
};

/// Runs a shell command line, capturing stdout and stderr separately.
RunResult run(const std::string& command_line);

/// The message of the rdsf::Error that `f` throws; empty when it throws none.
std::string error_message(const std::function<void()>& f);

/// The whole of a file, byte for byte; empty when it cannot be read (the tests then fail on what they expect).
std::string file_text(const std::filesystem::path& path);

/// Quotes a path for the shell.
std::string quote(const std::string& text);

/// The frames of a synthetic sequence as a frame source gives them: depth, colour (when p.rgb), index,
/// name, timestamp (index x 33,333 us) and p's camera model.
std::vector<DepthFrame> synthetic_frames(const synth::SynthParams& p);

}  // namespace rdsf::test
