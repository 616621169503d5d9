#include "support/test_support.hpp"

#include "rdsf/core/error.hpp"
#include "rdsf/synth/synth_sequence.hpp"

#include <array>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include <sys/wait.h>

namespace rdsf::test {

std::vector<DepthFrame> synthetic_frames(const synth::SynthParams& p) {
  synth::SynthSequence sequence(p);
  std::vector<DepthFrame> frames;
  for (int i = 0; i < p.frames; ++i) frames.push_back(sequence.frame(i).depth_frame(p.camera()));
  return frames;
}

std::filesystem::path realdata_dir() {
  const std::filesystem::path dir = std::filesystem::path(RDSF_SOURCE_DIR).parent_path() / "shared" / "realdata";
  std::error_code ec;
  return std::filesystem::is_directory(dir, ec) ? dir : std::filesystem::path();
}

TempDir::TempDir(const std::string& tag) {
  std::random_device random;
  path_ = std::filesystem::temp_directory_path() / (tag + "-" + std::to_string(random()) + std::to_string(random()));
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::string program(const std::string& name) {
  static const std::array<const char*, 9> folders = {"detector", "synth", "miner", "labeler",
                                                     "review", "trainer", "recorder", "bench", "adapt"};
  for (const char* folder : folders) {
    const std::filesystem::path candidate = std::filesystem::path(RDSF_BINARY_DIR) / folder / name;
    if (std::filesystem::exists(candidate)) return candidate.string();
  }
  return (std::filesystem::path(RDSF_BINARY_DIR) / name).string();
}

std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

std::string quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

RunResult run(const std::string& command_line) {
  TempDir scratch("rdsf-run");
  const std::string out_path = scratch / "out", err_path = scratch / "err";
  const std::string full = command_line + " >" + quote(out_path) + " 2>" + quote(err_path) + " </dev/null";
  const int status = std::system(full.c_str());
  RunResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  auto slurp = [](const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  result.out = slurp(out_path);
  result.err = slurp(err_path);
  return result;
}

std::string error_message(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace rdsf::test
