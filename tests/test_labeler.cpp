// rdsf-label headless: scripted answers with undo across a frame boundary and quit, resume, a SIGKILL in the
// middle of a session, and assisted mode on a synthetic sequence.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <sstream>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/evaluation/ground_truth.hpp"
#include "rdsf/frame/depth_png.hpp"
#include "support/depth_scenes.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

std::string label() { return test::quote(test::program("rdsf-label")); }

// Two frames, each with three candidates in this order: the person (nearest layer), the wall left of it,
// the wall right of it.
void write_two_frames(const test::TempDir& dir) { test::write_two_person_frames(dir / "frames"); }

test::RunResult run_label(const test::TempDir& dir, const std::string& keys, const std::string& extra = "") {
  std::ofstream(dir / "keys.txt") << keys;
  return test::run(label() + " --source " + test::quote(dir / "frames") + " --out " + test::quote(dir / "set") +
                   " --answers " + test::quote(dir / "keys.txt") + " " + extra);
}

int journal_answers(const test::TempDir& dir) {
  std::ifstream in(dir / "set/labeler-answers.tsv");
  int lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines - 1;
}

}  // namespace

TEST(Labeler, ScriptedAnswersWithUndoAcrossFramesAndQuit) {
  test::TempDir dir;
  write_two_frames(dir);
  // a#0 y, a#1 n, a#2 s, then on b#0: u (undoes a#2's skip), a#2 y, b#0 y, u (undoes it), b#0 n, q.
  const test::RunResult r = run_label(dir, "y n s u y y u n q");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const SampleSet set = SampleSet::open_read(dir / "set");
  ASSERT_EQ(set.records().size(), 2u) << r.err;
  const SampleRecord& first = set.records()[0];
  EXPECT_EQ(first.label, 1);
  EXPECT_EQ(first.origin, "labeler");
  EXPECT_EQ(first.frame, "a");
  EXPECT_EQ(first.strict_box, cv::Rect(230, 100, 180, 360));
  EXPECT_DOUBLE_EQ(first.layer_depth_mm, 2000.0);
  EXPECT_EQ(set.records()[1].frame, "a");
  EXPECT_EQ(set.records()[1].strict_box, cv::Rect(370, 0, 240, 480));  // the wall right of the person
  EXPECT_EQ(set.depth_crop(0).size(), cv::Size(64, 128));
  EXPECT_NE(r.err.find("quit"), std::string::npos) << r.err;

  // Resume: b#1 and b#2 are the only ones left.
  const test::RunResult again = run_label(dir, "y n");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const SampleSet resumed = SampleSet::open_read(dir / "set");
  ASSERT_EQ(resumed.records().size(), 3u);
  EXPECT_EQ(resumed.records()[2].frame, "b");
  EXPECT_EQ(resumed.records()[2].strict_box, cv::Rect(0, 0, 220, 480));  // b#1: the wall left of b's person
  // Nothing is left: a third run presents nothing and stores nothing.
  const test::RunResult done = run_label(dir, "y y y");
  ASSERT_EQ(done.exit_code, 0);
  EXPECT_EQ(SampleSet::open_read(dir / "set").records().size(), 3u);
  EXPECT_NE(done.err.find("answered 0"), std::string::npos) << done.err;
}

TEST(Labeler, KeepRejectedStoresNegatives) {
  test::TempDir dir;
  write_two_frames(dir);
  ASSERT_EQ(run_label(dir, "y n n n n n", "--keep-rejected").exit_code, 0);
  const SampleSet set = SampleSet::open_read(dir / "set");
  EXPECT_EQ(set.count(1), 1u);
  EXPECT_EQ(set.count(0), 5u);
}

TEST(Labeler, UnknownKeyIsAClearError) {
  test::TempDir dir;
  write_two_frames(dir);
  const test::RunResult r = run_label(dir, "y x");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("keys.txt: unknown key 'x'"), std::string::npos) << r.err;
  EXPECT_EQ(SampleSet::open_read(dir / "set").records().size(), 1u);  // the answer before it is kept
}

TEST(Labeler, NoDisplayWithoutAnswersExplains) {
  test::TempDir dir;
  write_two_frames(dir);
  const test::RunResult r = test::run("env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM " + label() +
                                      " --source " + test::quote(dir / "frames") + " --out " + test::quote(dir / "set"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("no display"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--answers"), std::string::npos) << r.err;
}

TEST(Labeler, KilledMidSessionLosesNothingAndResumes) {
  test::TempDir dir;
  write_two_frames(dir);
  int keys[2];
  ASSERT_EQ(pipe(keys), 0);
  const std::string command = label() + " --source " + test::quote(dir / "frames") + " --out " +
                              test::quote(dir / "set") + " --answers - --keep-rejected 2>/dev/null";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    dup2(keys[0], 0);
    close(keys[1]);
    execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  close(keys[0]);
  const std::string given = "y n y ";  // a#0 y, a#1 n (stored: --keep-rejected), a#2 y
  ASSERT_EQ(write(keys[1], given.data(), given.size()), static_cast<ssize_t>(given.size()));
  for (int i = 0; i < 200 && journal_answers(dir) < 3; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(25));
  ASSERT_EQ(journal_answers(dir), 3);
  kill(child, SIGKILL);  // while it waits for the fourth key
  int status = 0;
  waitpid(child, &status, 0);
  close(keys[1]);
  ASSERT_TRUE(WIFSIGNALED(status));

  const SampleSet after_kill = SampleSet::open_read(dir / "set");
  ASSERT_EQ(after_kill.records().size(), 3u);
  // The rerun starts at b#0: its first answer lands on frame b.
  ASSERT_EQ(run_label(dir, "n q", "--keep-rejected").exit_code, 0);
  const SampleSet resumed = SampleSet::open_read(dir / "set");
  ASSERT_EQ(resumed.records().size(), 4u);
  EXPECT_EQ(resumed.records()[3].frame, "b");
  EXPECT_EQ(resumed.records()[3].label, 0);
  std::set<std::tuple<std::string, int, int>> places;
  for (const SampleRecord& r : resumed.records()) places.insert({r.frame, r.strict_box.x, r.strict_box.y});
  EXPECT_EQ(places.size(), 4u);  // none twice
}

TEST(Labeler, AssistedModeAgreesWithGroundTruth) {
  test::TempDir dir;
  const test::RunResult synth = test::run(test::quote(test::program("rdsf-synth")) + " --out " +
                                          test::quote(dir / "synth") + " --frames 12 --people 1..2 --seed 3");
  ASSERT_EQ(synth.exit_code, 0) << synth.err;
  // Uncertain candidates (IoU 0.3-0.5) are answered 'n' here; everything else is answered from the truth.
  std::ofstream(dir / "keys") << std::string(400, 'n');
  const test::RunResult labelled = test::run(label() + " --source " + test::quote(dir / "synth") + " --out " +
                                             test::quote(dir / "set2") + " --truth " +
                                             test::quote(dir / "synth/boxes.csv") + " --answers " +
                                             test::quote(dir / "keys") + " --keep-rejected --box strict");
  ASSERT_EQ(labelled.exit_code, 0) << labelled.err;
  const GroundTruth truth = read_ground_truth(dir / "synth/boxes.csv");
  const SampleSet set = SampleSet::open_read(dir / "set2");
  ASSERT_GT(set.count(1), 0u);
  for (const SampleRecord& s : set.records()) {
    double best = 0;
    for (const TruthBox& t : truth.in(s.frame)) best = std::max(best, iou(t.box, s.strict_box));
    if (s.label == 1) {
      EXPECT_GE(best, 0.5) << s.frame;
    } else {
      EXPECT_LT(best, 0.5) << s.frame;
    }
  }
  EXPECT_NE(labelled.err.find("; 0 left unanswered"), std::string::npos) << labelled.err;
}

TEST(Labeler, TruthLabelsByTheExtentNotTheWidenedFittedBox) {
  // Each frame's person is a slab 40 px wide: its fitted box is widened to 0.3 of its height (108 and 114
  // px, IoU 0.37 and 0.35 with the truth), its extent is the truth. Labelling by overlap uses the extent,
  // so both are positives and the walls negatives, whatever fit.min_width_ratio says.
  test::TempDir dir;
  write_two_frames(dir);
  std::ofstream(dir / "boxes.csv") << "frame,person,x,y,w,h\na,1,300,100,40,360\nb,1,200,80,40,380\n";
  for (const char* ratio : {"0.3", "0"}) {
    const std::string set = std::string("set-") + ratio;
    const test::RunResult r = test::run(label() + " --source " + test::quote(dir / "frames") + " --out " +
                                        test::quote(dir / set) + " --truth " + test::quote(dir / "boxes.csv") +
                                        " --answers /dev/null --keep-rejected --fit-min-width-ratio " + ratio);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const SampleSet labelled = SampleSet::open_read(dir / set);
    EXPECT_EQ(labelled.count(1), 2u) << ratio;
    EXPECT_EQ(labelled.count(0), 4u) << ratio;
  }
}

// A truth that names none of the source's frames would answer every candidate "not a person" (with
// --keep-rejected, the people stored as negatives): refused before anything is written.
TEST(Labeler, TruthNamingNoneOfTheFramesIsRefusedBeforeAnythingIsWritten) {
  test::TempDir dir;
  write_two_frames(dir);
  std::ofstream(dir / "boxes.csv") << "frame,person,x,y,w,h\n0,1,300,100,40,360\n1,1,200,80,40,380\n";
  const test::RunResult r = test::run(label() + " --source " + test::quote(dir / "frames") + " --out " +
                                      test::quote(dir / "set") + " --truth " + test::quote(dir / "boxes.csv") +
                                      " --answers /dev/null --keep-rejected");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("rdsf-label: error: " + (dir / "boxes.csv") + ": names none of the 2 frames of " +
                       (dir / "frames") + " (it names e.g. '0', the source's first frame is 'a'"),
            std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "set"));
}

TEST(Labeler, AnswersRunningOutLeaveUncertainCandidatesAndComplete) {
  test::TempDir dir;
  write_two_frames(dir);
  const test::RunResult r = test::run(label() + " --source " + test::quote(dir / "frames") + " --out " +
                                      test::quote(dir / "set") + " --answers /dev/null");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("; 6 left unanswered"), std::string::npos) << r.err;
  EXPECT_EQ(SampleSet::open_read(dir / "set").records().size(), 0u);
}
