#pragma once
// A virtual X server (Xvfb) for tests of the programs' real windows, and its screen dumps (xwd -root).
#include <string>

#include <sys/types.h>

#include <opencv2/core.hpp>

namespace rdsf::test {

/// True when `tool` is on PATH.
bool have_tool(const char* tool);

/// Reads an XWD screen dump (xwd -root) of a TrueColor screen (24 or 32 bits per pixel) into a BGR image;
/// empty when it cannot.
cv::Mat3b read_xwd(const std::string& path);

/// Xvfb on display :(base + pid % 200), 1280x800x24, for the object's lifetime.
class VirtualScreen {
 public:
  explicit VirtualScreen(int base = 60);
  ~VirtualScreen();
  VirtualScreen(const VirtualScreen&) = delete;
  VirtualScreen& operator=(const VirtualScreen&) = delete;
  bool ready() const;
  const std::string& display() const { return display_; }

 private:
  std::string display_;
  pid_t pid_ = -1;
};

}  // namespace rdsf::test
