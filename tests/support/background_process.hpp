#pragma once
// A real program started in the background for a test (roscore, a ROS node), in its own process group
// with its output in a log file, and always stopped: stop() (and the destructor) sends SIGINT to the whole
// group (roscore's children too), waits up to a bound, then SIGKILLs the group.
#include <chrono>
#include <string>

#include <sys/types.h>

namespace rdsf::test {

class BackgroundProcess {
 public:
  /// Runs `command_line` with /bin/sh, stdout and stderr appended to `log_path`, stdin /dev/null.
  BackgroundProcess(const std::string& command_line, const std::string& log_path);
  ~BackgroundProcess();
  BackgroundProcess(const BackgroundProcess&) = delete;
  BackgroundProcess& operator=(const BackgroundProcess&) = delete;

  /// True while the process has not exited.
  bool running();
  /// SIGINT to the group, up to `grace` for the process to exit, then SIGKILL. Returns its exit code (128 +
  /// signal when killed by one; -1 when it could not be started). Idempotent.
  int stop(std::chrono::milliseconds grace = std::chrono::seconds(10));
  /// Waits up to `timeout` for the process to exit by itself; then stop(). Returns its exit code.
  int wait(std::chrono::milliseconds timeout);
  /// The log so far.
  std::string log() const;

 private:
  std::string log_path_;
  pid_t pid_ = -1;
  int exit_code_ = -1;
  bool exited_ = false;
};

/// A TCP port on 127.0.0.1 that was free a moment ago (bound to port 0, read, closed).
int free_tcp_port();

}  // namespace rdsf::test
