#include "adapt/run_program.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <deque>
#include <filesystem>
#include <fstream>

#include "rdsf/core/error.hpp"

extern char** environ;

namespace rdsf {

std::string sibling_program(const std::string& name) {
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe").parent_path();
  // The build tree's program folders (docs/architecture.md).
  const std::string folder = name == "rdsf-mine" ? "miner" : name == "rdsf-label" ? "labeler"
                             : name == "rdsf-train" ? "trainer" : name == "rdsf-detect" ? "detector"
                             : name == "rdsf-synth" ? "synth" : "";
  std::vector<std::filesystem::path> tried{self / name};
  if (!folder.empty()) tried.push_back(self.parent_path() / folder / name);
  for (const std::filesystem::path& p : tried) {
    if (::access(p.c_str(), X_OK) == 0) return p.string();
  }
  throw Error(tried.front().string() + ": " + name + " not found beside rdsf-adapt (build or install it too)");
}

namespace {

// `word` as one shell word: as it is when it holds only characters no shell treats specially, else in single
// quotes (a quote inside as '\'').
std::string shell_quoted(const std::string& word) {
  const bool plain = !word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                             "0123456789_-+=.,/:@%") == std::string::npos;
  if (plain) return word;
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

int run_program(const std::string& program, const std::vector<std::string>& args, const std::string& log) {
  std::vector<std::string> all{program};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  if (!log.empty()) {  // the command first, as a shell would take it, so that the step can be run by hand
    std::ofstream out(log, std::ios::app);
    out << "$";
    for (const std::string& a : all) out << " " << shell_quoted(a);
    out << "\n";
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!log.empty()) {
    posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    posix_spawn_file_actions_adddup2(&actions, 2, 1);
  }
  pid_t pid = 0;
  const int started = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (started != 0) throw Error(program + ": cannot be started (" + std::to_string(started) + ")");
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw Error(program + ": lost track of it (waitpid)");
  }
  if (WIFSIGNALED(status)) throw Error(program + ": killed by signal " + std::to_string(WTERMSIG(status)));
  return WEXITSTATUS(status);
}

std::vector<std::string> log_lines(const std::string& log, const std::string& prefix, std::size_t count) {
  std::ifstream in(log);
  std::deque<std::string> kept;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) != 0) continue;
    kept.push_back(line);
    if (kept.size() > count) kept.pop_front();
  }
  return {kept.begin(), kept.end()};
}

}  // namespace rdsf
