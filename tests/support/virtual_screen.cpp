#include "support/virtual_screen.hpp"

#include <chrono>
#include <csignal>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <thread>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "support/test_support.hpp"

namespace rdsf::test {

bool have_tool(const char* tool) { return run(std::string("command -v ") + tool).exit_code == 0; }

cv::Mat3b read_xwd(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto u32 = [&](std::size_t field) {
    const std::size_t at = field * 4;
    return at + 4 <= b.size() ? (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) |
                                    (std::uint32_t{b[at + 2]} << 8) | b[at + 3]
                              : 0U;
  };
  const std::uint32_t header = u32(0), width = u32(4), height = u32(5), byte_order = u32(7), bpp = u32(11),
                      line = u32(12), colours = u32(19);
  if ((bpp != 32 && bpp != 24) || width == 0 || height == 0) return {};
  const std::size_t bytes_per_pixel = bpp / 8;
  const std::size_t pixels = header + colours * 12;
  if (pixels + std::size_t{line} * height > b.size()) return {};
  cv::Mat3b image(static_cast<int>(height), static_cast<int>(width));
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const unsigned char* p = &b[pixels + std::size_t{y} * line + std::size_t{x} * bytes_per_pixel];
      // LSBFirst: B G R (X); MSBFirst: (X) R G B.
      const unsigned char* last = p + bytes_per_pixel - 1;
      image(static_cast<int>(y), static_cast<int>(x)) =
          byte_order == 0 ? cv::Vec3b(p[0], p[1], p[2]) : cv::Vec3b(last[0], last[-1], last[-2]);
    }
  }
  return image;
}

VirtualScreen::VirtualScreen(int base) : display_(":" + std::to_string(base + getpid() % 200)) {
  pid_ = fork();
  if (pid_ == 0) {
    execlp("Xvfb", "Xvfb", display_.c_str(), "-screen", "0", "1280x800x24", "-nolisten", "tcp",
           static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int i = 0; i < 100 && !ready(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
}

VirtualScreen::~VirtualScreen() {
  if (pid_ > 0) {
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
  }
}

bool VirtualScreen::ready() const { return run("DISPLAY=" + display_ + " xdotool getmouselocation").exit_code == 0; }

}  // namespace rdsf::test
