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
#include "support/virtual_screen.hpp"

using namespace rdsf;

TEST(LabelerWindow, KeysTypedIntoTheRealWindowAreStored) {
  RDSF_REQUIRE_REALDATA();
  if (!test::have_tool("Xvfb") || !test::have_tool("xdotool") || !test::have_tool("xwd")) GTEST_SKIP() << "Xvfb, xdotool or xwd missing";
  test::VirtualScreen screen;
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
    // Waits for the count to become `expect`, up or down (an undo lowers it): on a loaded machine the key
    // is handled a while after xdotool returns.
    for (int i = 0; i < 100 && samples() != expect; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
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
  const cv::Mat3b shot = test::read_xwd(dump);
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
