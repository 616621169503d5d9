// The labeler's real window: under a virtual X server (Xvfb) rdsf-label opens its highgui window on the real
// frames, xdotool types the keys a person would, and the stored samples are checked. A screenshot of the
// screen is kept as a test artefact: <build>/test-artefacts/labeler-window.png.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include <opencv2/imgcodecs.hpp>

#include "rdsf/dataset/sample_set.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

bool have(const char* tool) { return test::run(std::string("command -v ") + tool).exit_code == 0; }

// Reads an XWD screen dump (xwd -root) of a TrueColor screen (24 or 32 bits per pixel) into a BGR image.
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

class VirtualScreen {
 public:
  VirtualScreen() : display_(":" + std::to_string(60 + getpid() % 200)) {
    pid_ = fork();
    if (pid_ == 0) {
      execlp("Xvfb", "Xvfb", display_.c_str(), "-screen", "0", "1280x800x24", "-nolisten", "tcp",
             static_cast<char*>(nullptr));
      _exit(127);
    }
    for (int i = 0; i < 100 && !ready(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ~VirtualScreen() {
    if (pid_ > 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  bool ready() const { return test::run("DISPLAY=" + display_ + " xdotool getmouselocation").exit_code == 0; }
  const std::string& display() const { return display_; }

 private:
  std::string display_;
  pid_t pid_ = -1;
};

}  // namespace

TEST(LabelerWindow, KeysTypedIntoTheRealWindowAreStored) {
  RDSF_REQUIRE_REALDATA();
  if (!have("Xvfb") || !have("xdotool") || !have("xwd")) GTEST_SKIP() << "Xvfb, xdotool or xwd missing";
  VirtualScreen screen;
  ASSERT_TRUE(screen.ready()) << "Xvfb did not start";
  test::TempDir dir;
  const std::string set = dir / "set";
  const std::string env = "DISPLAY=" + screen.display() + " ";
  const std::string command = "exec " + test::quote(test::program("rdsf-label")) + " --source " +
                              test::quote((test::realdata_dir() / "people").string()) + " --out " + test::quote(set) +
                              " --keep-rejected >" + test::quote(dir / "out") + " 2>" + test::quote(dir / "err");
  const pid_t labeler = fork();
  ASSERT_GE(labeler, 0);
  if (labeler == 0) {
    setenv("DISPLAY", screen.display().c_str(), 1);
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  const test::RunResult window = test::run(env + "timeout 30 xdotool search --sync --onlyvisible --name '^rdsf-label$'");
  ASSERT_EQ(window.exit_code, 0) << "no window appeared";
  const std::string id = window.out.substr(0, window.out.find('\n'));
  auto samples = [&] {
    try {
      return SampleSet::open_read(set).records().size();
    } catch (const std::exception&) {
      return std::size_t{0};
    }
  };
  auto type = [&](const std::string& key, std::size_t expect) {
    ASSERT_EQ(test::run(env + "xdotool key --window " + id + " " + key).exit_code, 0);
    for (int i = 0; i < 100 && samples() < expect; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_EQ(samples(), expect) << "after key " << key;
  };
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // let the first candidate be drawn
  type("y", 1);
  type("n", 2);  // --keep-rejected: stored as a negative
  type("y", 3);
  type("BackSpace", 2);  // undo
  std::this_thread::sleep_for(std::chrono::milliseconds(500));

  // The screenshot a person would see, kept as an artefact.
  const std::string dump = dir / "screen.xwd";
  ASSERT_EQ(test::run(env + "xwd -root -silent -out " + test::quote(dump)).exit_code, 0);
  const cv::Mat3b shot = read_xwd(dump);
  ASSERT_FALSE(shot.empty()) << "cannot read the screen dump " << dump << " ("
                             << (std::filesystem::exists(dump) ? std::filesystem::file_size(dump) : 0) << " bytes)";
  EXPECT_GT(cv::countNonZero(shot.reshape(1)), 10000);  // something is drawn
  const std::filesystem::path artefacts = std::filesystem::path(RDSF_BINARY_DIR) / "test-artefacts";
  std::filesystem::create_directories(artefacts);
  cv::imwrite((artefacts / "labeler-window.png").string(), shot);

  type("q", 2);
  int status = 0;
  for (int i = 0; i < 100 && waitpid(labeler, &status, WNOHANG) == 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_TRUE(WIFEXITED(status)) << "the labeler did not quit on q";
  EXPECT_EQ(WEXITSTATUS(status), 0);
  const SampleSet stored = SampleSet::open_read(set);
  ASSERT_EQ(stored.records().size(), 2u);
  EXPECT_EQ(stored.records()[0].label, 1);
  EXPECT_EQ(stored.records()[1].label, 0);
  std::ifstream err(dir / "err");
  const std::string messages((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  EXPECT_NE(messages.find("key to next candidate"), std::string::npos) << messages;
  std::cout << messages;
}
