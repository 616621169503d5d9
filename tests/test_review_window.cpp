// The model-assisted labeler and the review in their real windows, under a virtual X server (Xvfb), on a
// synthetic recording with colour: xdotool types the keys a person would, the stored samples are checked,
// and screenshots are kept as test artefacts (<build>/test-artefacts/): labeler-uncertain.png (the reason a
// candidate is asked and the model's answers in the status line), labeler-zoom.png (+ twice) and
// review-grid.png (the review's grid after a flip and a retraction).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "rdsf/dataset/sample_set.hpp"
#include "support/test_support.hpp"
#include "support/virtual_screen.hpp"

using namespace rdsf;

namespace {

class WindowProgram {
 public:
  WindowProgram(const test::VirtualScreen& screen, const std::string& command, const std::string& title)
      : env_("DISPLAY=" + screen.display() + " ") {
    pid_ = fork();
    if (pid_ == 0) {
      setenv("DISPLAY", screen.display().c_str(), 1);
      execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    const test::RunResult window = test::run(env_ + "timeout 60 xdotool search --sync --onlyvisible --name '^" + title + "$'");
    id_ = window.out.substr(0, window.out.find('\n'));
  }
  ~WindowProgram() {
    if (pid_ > 0 && waitpid(pid_, nullptr, WNOHANG) == 0) {
      kill(pid_, SIGTERM);
      waitpid(pid_, nullptr, 0);
    }
  }
  bool has_window() const { return !id_.empty(); }
  void key(const std::string& k) const {
    EXPECT_EQ(test::run(env_ + "xdotool key --window " + id_ + " " + k).exit_code, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
  }
  cv::Mat3b screenshot(const test::TempDir& dir, const std::string& artefact) const {
    const std::string dump = dir / "screen.xwd";
    EXPECT_EQ(test::run(env_ + "xwd -root -silent -out " + test::quote(dump)).exit_code, 0);
    const cv::Mat3b shot = test::read_xwd(dump);
    const std::filesystem::path artefacts = std::filesystem::path(RDSF_BINARY_DIR) / "test-artefacts";
    std::filesystem::create_directories(artefacts);
    if (shot.empty()) return shot;
    // The window only: the bounding box of what is drawn on the black screen.
    cv::Mat1b drawn;
    cv::cvtColor(shot, drawn, cv::COLOR_BGR2GRAY);
    const cv::Rect window = cv::boundingRect(drawn > 0);
    cv::imwrite((artefacts / artefact).string(), shot(window));
    return shot;
  }
  int wait_exit() {
    int status = 0;
    for (int i = 0; i < 100 && waitpid(pid_, &status, WNOHANG) == 0; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    pid_ = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

 private:
  std::string env_, id_;
  pid_t pid_ = -1;
};

std::size_t stored(const std::string& set) {
  try {
    return SampleSet::open_read(set).records().size();
  } catch (const std::exception&) {
    return 0;
  }
}

/// The set's size once it is `expect` (keys are handled a while after xdotool returns on a loaded
/// machine), or after 5 s whatever it is then.
std::size_t stored_once(const std::string& set, std::size_t expect) {
  for (int i = 0; i < 100 && stored(set) != expect; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  return stored(set);
}

}  // namespace

TEST(ReviewWindow, ModelAssistedLabelerAndReviewGridTakeKeys) {
  if (!test::have_tool("Xvfb") || !test::have_tool("xdotool") || !test::have_tool("xwd")) {
    GTEST_SKIP() << "Xvfb, xdotool or xwd missing";
  }
  test::VirtualScreen screen(300);
  ASSERT_TRUE(screen.ready()) << "Xvfb did not start";
  test::TempDir dir;
  ASSERT_EQ(test::run(test::quote(test::program("rdsf-synth")) + " --out " + test::quote(dir / "synth") +
                      " --frames 15 --people 1..3 --seed 6 --rgb")
                .exit_code,
            0);
  const std::string set = dir / "set";
  const std::string models = test::quote(std::string(RDSF_SOURCE_DIR) + "/models");
  std::size_t by_model = 0;
  {
    WindowProgram labeler(screen,
                          test::quote(test::program("rdsf-label")) + " --source " + test::quote(dir / "synth") +
                              " --out " + test::quote(set) + " --model people --models-dir " + models +
                              " --ask uncertain --keep-rejected 2>" + test::quote(dir / "label.err"),
                          "rdsf-label");
    ASSERT_TRUE(labeler.has_window());
    // The whole session is scored first and the model's answers stored before the first candidate shows.
    for (int i = 0; i < 60; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(500));
      const std::size_t now = stored(set);
      if (now > 0 && now == by_model) break;
      by_model = now;
    }
    EXPECT_GT(by_model, 0u);
    labeler.key("y");
    labeler.key("n");
    EXPECT_EQ(stored_once(set, by_model + 2), by_model + 2);
    EXPECT_GT(cv::countNonZero(labeler.screenshot(dir, "labeler-uncertain.png").reshape(1)), 10000);
    labeler.key("plus");
    labeler.key("plus");
    labeler.screenshot(dir, "labeler-zoom.png");
    labeler.key("y");  // zooming answered nothing: this is the third human answer
    EXPECT_EQ(stored_once(set, by_model + 3), by_model + 3);
    labeler.key("q");
    EXPECT_EQ(labeler.wait_exit(), 0);
  }
  {
    WindowProgram review(screen,
                         test::quote(test::program("rdsf-review")) + " --set " + test::quote(set) +
                             " --model people --models-dir " + models + " 2>" + test::quote(dir / "review.err"),
                         "rdsf-review");
    ASSERT_TRUE(review.has_window());
    std::this_thread::sleep_for(std::chrono::milliseconds(800));
    review.key("f");      // flip the most suspicious
    review.key("Right");
    review.key("x");      // retract the next one
    stored_once(set, by_model + 3 - 1);
    const SampleSet after = SampleSet::open_read(set);
    EXPECT_EQ(after.records().size(), by_model + 3 - 1);  // +1 corrected, -1 flipped original, -1 retracted
    EXPECT_EQ(after.records().back().origin, "review");
    EXPECT_GT(cv::countNonZero(review.screenshot(dir, "review-grid.png").reshape(1)), 10000);
    review.key("q");
    EXPECT_EQ(review.wait_exit(), 0);
  }
}
