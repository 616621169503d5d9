// rdsf-adapt: bad input refused with one line before anything is written (budget 0, depth
// that is not millimetres, a truth naming frames not in the room, an "empty" recording with people), also on
// the rerun of a run that has answers (nothing answered lost), and a run stopped after its answers
// resumes without asking again, and a run killed (SIGKILL, the step's program with it) resumes. Small
// synthetic rooms rendered by rdsf-synth; the shipped model people.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include <opencv2/imgproc.hpp>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/frame/depth_png.hpp"
#include "rdsf/labeling/answer_journal.hpp"
#include "support/depth_scenes.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

std::string adapt() { return test::quote(test::program("rdsf-adapt")); }

test::RunResult render(const std::string& out, const std::string& extra) {
  return test::run(test::quote(test::program("rdsf-synth")) + " --out " + test::quote(out) +
                   " --force --people 1..2 --clip-frames 30 --seed 7 " + extra);
}

std::string models_dir() { return std::string(RDSF_SOURCE_DIR) + "/models"; }

// A models folder of the test's own holding the shipped default model (the newest version of 'people'): a
// run that should stop early but does not (a guard that stops holding) trains into it, not into the source
// tree's models/.
std::string own_models(const test::TempDir& dir) {
  const std::filesystem::path models = dir.path() / "models";
  const std::filesystem::path shipped = resolve_model("people", models_dir());
  std::filesystem::create_directories(models / "people");
  std::filesystem::copy_file(shipped, models / "people" / shipped.filename());
  return test::quote(models.string());
}

// A models folder of the test's own holding people/v2, and the command that adapts the 60-frame room
// rendered in `dir` with its truth, headless (`budget` answers, 3 rounds, no base) into `dir`/out.
struct SmallRoomRun {
  std::filesystem::path models;
  std::string command;
};
SmallRoomRun small_room_run(const test::TempDir& dir, int budget, const std::string& version = "v2") {
  SmallRoomRun run{dir.path() / "models", ""};
  std::filesystem::create_directories(run.models / "people");
  std::filesystem::copy_file(models_dir() + "/people/" + version + ".yml", run.models / ("people/" + version + ".yml"));
  run.command = adapt() + " --source " + test::quote(dir / "room") + " --truth " + test::quote(dir / "room/boxes.csv") +
                " --out " + test::quote(dir / "out") + " --name room --budget " + std::to_string(budget) +
                " --rounds 3 --threads 2 --base-frames 0 --models-dir " + test::quote(run.models.string());
  return run;
}

// Whether the model file states --local-front 70 among its detection options.
bool states_local_front(const std::filesystem::path& model) {
  const RecordedParameters stated = BoostedModel::load(model.string()).detection_options();
  return std::find(stated.begin(), stated.end(), std::make_pair(std::string("local_front"), std::string("70"))) !=
         stated.end();
}

// `text` with its one `from` replaced by `to`.
std::string replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("'" + from + "' not in the command");
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST(Adapt, BudgetZeroIsAUsageError) {
  test::TempDir dir;
  const test::RunResult r = test::run(adapt() + " --source x --out " + test::quote(dir / "out") + " --name room --budget 0");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--budget 0"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(Adapt, ATruthOfOtherFramesIsRefusedBeforeAnythingIsWritten) {
  test::TempDir dir;
  ASSERT_EQ(render(dir / "room", "--frames 30").exit_code, 0);
  std::ofstream(dir / "truth.csv") << "frame,person,x,y,w,h\n000003,1,100,100,50,100\nnot-a-frame,1,100,100,50,100\n";
  const test::RunResult r = test::run(adapt() + " --source " + test::quote(dir / "room") + " --truth " + test::quote(dir / "truth.csv") +
                " --out " + test::quote(dir / "out") + " --name room --models-dir " + own_models(dir));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(dir / "truth.csv"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not-a-frame"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

// How it is noticed: the model, with the tracker, follows one person over 5 frames at P(person) >= 0.7
// (rdsf/pipeline/room_presence.hpp); refused before anything is written.
TEST(Adapt, AnEmptyRecordingWithPeopleIsRefused) {
  test::TempDir dir;
  ASSERT_EQ(render(dir / "room", "--frames 30").exit_code, 0);
  const test::RunResult r = test::run(adapt() + " --source " + test::quote(dir / "room") + " --empty " +
                                      test::quote(dir / "room") + " --truth " + test::quote(dir / "room/boxes.csv") +
                                      " --out " + test::quote(dir / "out") + " --name room --models-dir " + own_models(dir));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("not empty"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(dir / "room"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--trust-empty"), std::string::npos) << r.err;  // the way out, when nobody is there
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

// --trust-empty: the user has looked and nobody is there; the recording is used, and the run says what the
// model followed in it. (Here it stops at training: the base set given does not exist.)
TEST(Adapt, AnEmptyRecordingTheUserVouchesForIsUsed) {
  test::TempDir dir;
  ASSERT_EQ(render(dir / "room", "--frames 30").exit_code, 0);
  const std::string command = adapt() + " --source " + test::quote(dir / "room") + " --empty " +
                              test::quote(dir / "room") + " --truth " + test::quote(dir / "room/boxes.csv") +
                              " --out " + test::quote(dir / "out") + " --name room --budget 2 --threads 2" +
                              " --base-pos " + test::quote(dir / "missing") + " --models-dir " + own_models(dir);
  const test::RunResult r = test::run(command + " --trust-empty");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("taken as empty (--trust-empty) although"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rdsf-train failed"), std::string::npos) << r.err;  // it went on to the end
  EXPECT_TRUE(std::filesystem::exists(dir / "out/sets/room-negatives/manifest.yml"));
  // Each step's log begins with its command, to be run by hand; the room's model continues people/v3 but is
  // not given its base's --operating-tar (measured worse: docs/adapting-to-your-room.md).
  const std::string train_log = test::file_text(dir / "out/logs/train.log");
  EXPECT_EQ(train_log.rfind("$ ", 0), 0u) << train_log;
  EXPECT_NE(train_log.find("/rdsf-train --models-dir "), std::string::npos) << train_log;
  EXPECT_NE(train_log.find(" --init people "), std::string::npos) << train_log;
  EXPECT_EQ(train_log.find("--operating-tar"), std::string::npos) << train_log;
  const test::RunResult usage = test::run(adapt() + " --source x --out " + test::quote(dir / "o2") +
                                          " --name room --trust-empty");
  EXPECT_EQ(usage.exit_code, 2) << usage.err;
  EXPECT_NE(usage.err.find("--trust-empty needs --empty"), std::string::npos) << usage.err;
}

TEST(Adapt, AStoppedRunResumesWithoutAskingAgain) {
  test::TempDir dir;
  ASSERT_EQ(render(dir / "room", "--frames 60").exit_code, 0);
  ASSERT_EQ(render(dir / "empty", "--frames 30 --empty").exit_code, 0);
  const std::filesystem::path models = dir.path() / "models";
  std::filesystem::create_directories(models / "people");
  std::filesystem::copy_file(models_dir() + "/people/v2.yml", models / "people/v2.yml");
  const std::string common = adapt() + " --source " + test::quote(dir / "room") + " --empty " + test::quote(dir / "empty") +
                             " --truth " + test::quote(dir / "room/boxes.csv") + " --out " + test::quote(dir / "out") +
                             " --name room --budget 6 --rounds 3 --threads 2 --base-frames 60 --holdout-check off" +
                             " --models-dir " + test::quote(models.string());
  // The first run fails at training (a base set that does not exist), after its negatives and answers.
  test::RunResult r = test::run(common + " --base-pos " + test::quote(dir / "missing"));
  ASSERT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("rdsf-train failed"), std::string::npos) << r.err;
  const std::string journal = dir / "out/sets/room/labeler-answers.tsv";
  long human = 0;
  {
    const AnswerJournal j(journal);
    for (const JournalEntry& e : j.in_force()) human += e.by == "human" ? 1 : 0;
  }
  EXPECT_GT(human, 0);
  EXPECT_LE(human, 6);
  const auto journal_size = std::filesystem::file_size(journal);
  const std::string state = test::file_text(dir / "out/adapt-state.tsv");
  // Bad input on the rerun: refused with one line naming the file, and nothing answered is lost.
  std::filesystem::create_directories(dir / "metres");
  write_png_atomically(dir / "metres/000000.depth.png", cv::Mat1w(480, 640, static_cast<std::uint16_t>(3)));
  std::ofstream(dir / "truth.csv") << "frame,person,x,y,w,h\n000003,1,100,100,50,100\nnot-a-frame,1,100,100,50,100\n";
  const struct {
    std::string command, names, says;
    int exit_code;
  } bad[] = {
      {replace(common, "--budget 6", "--budget 0"), "--budget 0", "give 1 or more", 2},
      {replace(common, "--truth " + test::quote(dir / "room/boxes.csv"), "--truth " + test::quote(dir / "truth.csv")),
       dir / "truth.csv", "not-a-frame", 1},
      {replace(common, "--source " + test::quote(dir / "room"), "--source " + test::quote(dir / "metres")),
       dir / "metres", "not millimetres", 1},
      {replace(common, "--empty " + test::quote(dir / "empty"), "--empty " + test::quote(dir / "room")),
       dir / "room", "not empty", 1},
  };
  for (const auto& b : bad) {
    r = test::run(b.command);
    EXPECT_EQ(r.exit_code, b.exit_code) << b.command << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(b.names), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(b.says), std::string::npos) << r.err;
    EXPECT_EQ(std::filesystem::file_size(journal), journal_size) << b.command;
    EXPECT_EQ(test::file_text(dir / "out/adapt-state.tsv"), state) << b.command;
  }
  // The rerun trains with the room's samples weighing twice a base sample: its sets given twice.
  r = test::run(common + " --room-weight 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("answers: done before"), std::string::npos) << r.err;
  EXPECT_EQ(std::filesystem::file_size(journal), journal_size);  // nothing asked again
  EXPECT_TRUE(std::filesystem::exists(models / "room/v1.yml"));
  std::ifstream model(models / "room/v1.yml");
  const std::string text((std::istreambuf_iterator<char>(model)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("adapted_room"), std::string::npos);
  EXPECT_NE(text.find("adapted_from"), std::string::npos);
  EXPECT_NE(text.find("init"), std::string::npos);  // continued from people/v2
  // Without base sets the rerun rendered its own (60 frames with people, 30 empty) and trained with them.
  EXPECT_NE(r.err.find("a synthetic base rendered in"), std::string::npos) << r.err;
  EXPECT_NE(text.find(dir / "out/base/people"), std::string::npos);
  EXPECT_NE(text.find(dir / "out/base/negatives"), std::string::npos);
  EXPECT_GT(SampleSet::open_read(dir / "out/base/people").records().size(), 20u);
  EXPECT_GT(SampleSet::open_read(dir / "out/base/negatives").records().size(), 30u);
  int room_as_pos = 0, base_as_pos = 0;
  const BoostedModel adapted = BoostedModel::load(models / "room/v1.yml");
  for (const SampleSetUse& use : adapted.training().sample_sets) {
    if (use.role != "pos") continue;
    room_as_pos += use.path == dir / "out/sets/room" ? 1 : 0;
    base_as_pos += use.path == dir / "out/base/people" ? 1 : 0;
  }
  EXPECT_EQ(room_as_pos, 2);
  EXPECT_EQ(base_as_pos, 1);
  // A room's model states no operating point (read at P >= 0.5 of its own calibration), and its training's
  // command heads the step's log.
  EXPECT_FALSE(adapted.operating_point());
  EXPECT_EQ(test::file_text(dir / "out/logs/train.log").rfind("$ ", 0), 0u);
}

// --base-cache: the base is rendered once into the cache and its sets cut once per set of analyser options; a second
// run (another work folder) renders nothing and trains with the same sets. Both runs' states name them.
TEST(Adapt, RunsSharingABaseCacheRenderItOnce) {
  test::TempDir dir;
  ASSERT_EQ(render(dir / "room", "--frames 40").exit_code, 0);
  const SmallRoomRun run = small_room_run(dir, 4);
  const std::string cache = dir / "cache";
  const std::string common = replace(run.command, "--base-frames 0", "--base-frames 60 --base-cache " + test::quote(cache)) +
                             " --holdout-check off --try-switches off --hole-gap 20 --base-cut stated";
  // What a killed run left half made (its process gone: no such process id) is removed, not reused.
  const std::filesystem::path left = std::filesystem::path(cache) / "frames-60.part-2147483646";
  std::filesystem::create_directories(left);
  test::RunResult r = test::run(common);
  EXPECT_FALSE(std::filesystem::exists(left));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::filesystem::path sets = std::filesystem::path(cache) / "sets-60-hole-gap-20";
  EXPECT_NE(r.err.find("base: rendering"), std::string::npos) << r.err;
  ASSERT_TRUE(std::filesystem::exists(sets / "people/manifest.yml"));
  ASSERT_TRUE(std::filesystem::exists(sets / "negatives/manifest.yml"));
  EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(cache) / "frames-60/boxes.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out/base"));  // nothing in the work folder
  EXPECT_NE(test::file_text(dir / "out/adapt-state.tsv").find((sets / "people").string()), std::string::npos);
  const auto rendered = std::filesystem::last_write_time(std::filesystem::path(cache) / "frames-60");
  const std::size_t people = SampleSet::open_read((sets / "people").string()).records().size();

  r = test::run(replace(replace(common, "--out " + test::quote(dir / "out"), "--out " + test::quote(dir / "out2")),
                        "--name room", "--name room2"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("base: rendering"), std::string::npos) << r.err;  // reused, not rendered again
  EXPECT_EQ(std::filesystem::last_write_time(std::filesystem::path(cache) / "frames-60"), rendered);
  EXPECT_EQ(SampleSet::open_read((sets / "people").string()).records().size(), people);  // not cut again
  int base_as_pos = 0;
  const BoostedModel second = BoostedModel::load(run.models / "room2/v1.yml");
  for (const SampleSetUse& use : second.training().sample_sets) {
    base_as_pos += use.role == "pos" && use.path == (sets / "people").string() ? 1 : 0;
  }
  EXPECT_EQ(base_as_pos, 1);
  for (const auto& entry : std::filesystem::directory_iterator(cache)) {  // no folder left half made
    EXPECT_EQ(entry.path().filename().string().find(".part-"), std::string::npos) << entry.path();
  }
  // A run without the cache renders the same base into its work folder and trains the same model (the base's
  // frames are named alike in both places, and validation groups are named by that folder).
  r = test::run(replace(replace(replace(common, "--out " + test::quote(dir / "out"), "--out " + test::quote(dir / "out3")),
                                "--name room", "--name room3"),
                        "--base-cache " + test::quote(cache), ""));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "out3/base/frames-60/boxes.csv"));
  EXPECT_EQ(BoostedModel::load(run.models / "room3/v1.yml").weak_classifiers(),
            BoostedModel::load(run.models / "room/v1.yml").weak_classifiers());
  // With base sets of one's own, the cache has nothing to keep: a usage error naming it.
  r = test::run(common + " --base-pos " + test::quote(sets / "people"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--base-cache"), std::string::npos) << r.err;
}

// Any resolution (issue 36): a room seen by a Kinect v2-size camera (512x424, 70.6 x 60 degrees: the
// camera.yml rdsf-synth writes beside the frames) is adapted like a Kinect v1 room: every step cuts its crops
// by the room's camera model, and the room's samples train with the Kinect v1 base. Without --empty the
// frames taken as empty (its last 60: nobody in them) are mined from a list file, beside which the room's
// camera.yml goes (a list's frames take the camera.yml of the list's folder).
TEST(Adapt, ARoomOfAnotherCameraIsAdapted) {
  test::TempDir dir;
  ASSERT_EQ(test::run(test::quote(test::program("rdsf-synth")) + " --out " + test::quote(dir / "room") +
                      " --force --frames 90 --people 0..1 --clip-frames 30 --seed 7 --size 512x424 --fov 70.6x60")
                .exit_code,
            0);
  ASSERT_TRUE(std::filesystem::exists(dir / "room/camera.yml"));
  const std::filesystem::path models = dir.path() / "models";
  std::filesystem::create_directories(models / "people");
  std::filesystem::copy_file(models_dir() + "/people/v2.yml", models / "people/v2.yml");
  const test::RunResult r = test::run(
      adapt() + " --source " + test::quote(dir / "room") + " --truth " + test::quote(dir / "room/boxes.csv") +
      " --out " + test::quote(dir / "out") + " --name room --budget 6 --rounds 3 --threads 2 --base-frames 60" +
      " --models-dir " + test::quote(models.string()) + " --eval " + test::quote(dir / "room"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(models / "room/v1.yml"));
  const std::string report = test::file_text(dir / "out/report.txt");
  EXPECT_NE(report.find("validation AUC"), std::string::npos) << report;
  // --eval (here the room's own 90 frames, to reach the report): before and after from one rdsf-detect run of
  // both models, and their difference; 90 frames are one clip of 100, so no interval over clips.
  EXPECT_TRUE(std::regex_search(report, std::regex(R"(before [01]\.\d{3} \(people\), after [01]\.\d{3}; after - )"
                                                   R"(before [-+][01]\.\d{3} \(one clip: no interval\))")))
      << report;
  EXPECT_NE(test::file_text(dir / "out/adapt-state.tsv").find("tar_difference\t"), std::string::npos);
  EXPECT_NE(test::file_text(dir / "out/empty-frames/frames.txt").find("000089.depth.png"), std::string::npos);
  EXPECT_EQ(test::file_text(dir / "out/empty-frames/camera.yml"), test::file_text(dir / "room/camera.yml"));
  // The room's samples are the 512x424 frames' candidates: answered ones and the mined negatives.
  const SampleSet room = SampleSet::open_read(dir / "out/sets/room");
  const SampleSet negatives = SampleSet::open_read(dir / "out/sets/room-negatives");
  EXPECT_GT(room.records().size(), 0u);
  EXPECT_GT(negatives.records().size(), 0u);
  for (const SampleRecord& rec : negatives.records()) {
    EXPECT_LE(rec.strict_box.x + rec.strict_box.width, 512) << rec.frame;
    EXPECT_LE(rec.strict_box.y + rec.strict_box.height, 424) << rec.frame;
  }
  // With the small base rendered here the held-out check is on (--holdout-check auto): the trial's sets hold the
  // samples of the earlier 45 frames, the negatives mined from the room's own frames split with them (the frames
  // taken as empty are among the last, so they all fall in the later half and are scored there).
  EXPECT_NE(report.find("held-out check (the trial trained in "), std::string::npos) << report;
  EXPECT_NE(report.find("later 45 frames, "), std::string::npos) << report;
  const SampleSet earlier = SampleSet::open_read(dir / "out/check/earlier-room");
  EXPECT_GT(earlier.records().size(), 0u);
  EXPECT_LT(earlier.records().size(), room.records().size());
  for (const SampleRecord& rec : earlier.records()) EXPECT_LT(std::stoi(rec.frame), 45);
  const SampleSet earlier_negatives = SampleSet::open_read(dir / "out/check/earlier-room-negatives");
  EXPECT_LT(earlier_negatives.records().size(), negatives.records().size());
  for (const SampleRecord& rec : earlier_negatives.records()) EXPECT_LT(std::stoi(rec.frame), 45);
  EXPECT_TRUE(std::filesystem::exists(dir / "out/check/models/trial/v1.yml"));
}

// The held-out check asked for with no base: the trial of the earlier half against people/v2 on the later
// half's labelled candidates decides the room's model, which is either trained (v2's rounds and 3 more) or
// people/v2 itself stating the room (every weak classifier inherited, so scored as v2 is). The choice is pinned.
TEST(Adapt, TheHoldoutCheckDecidesBetweenTheTrialAndTheModelAsGiven) {
  test::TempDir dir;
  ASSERT_EQ(render(dir / "room", "--frames 60").exit_code, 0);
  const SmallRoomRun run = small_room_run(dir, 8);
  test::RunResult r = test::run(run.command + " --holdout-check on");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("rdsf-adapt: check: later 30 frames, "), std::string::npos) << r.err;
  const std::string state = test::file_text(dir / "out/adapt-state.tsv");
  const bool base_kept = state.find("check\tbase kept") != std::string::npos;
  EXPECT_TRUE(base_kept || state.find("check\ttrial kept") != std::string::npos) << state;
  const SampleSet earlier = SampleSet::open_read(dir / "out/check/earlier-room");
  EXPECT_GT(earlier.records().size(), 0u);
  for (const SampleRecord& rec : earlier.records()) EXPECT_LT(std::stoi(rec.frame), 30);
  const BoostedModel v2 = BoostedModel::load(models_dir() + "/people/v2.yml");
  const BoostedModel room = BoostedModel::load((run.models / "room/v1.yml").string());
  EXPECT_TRUE(room.training().adapted_to_a_room());
  EXPECT_EQ(room.weak_classifiers().size(), v2.weak_classifiers().size() + (base_kept ? 0 : 3)) << state;
  const auto& p = room.training().parameters;
  EXPECT_EQ(std::count_if(p.begin(), p.end(), [](const auto& kv) { return kv.first == "adapted_check"; }),
            base_kept ? 1 : 0);
  r = test::run(run.command + " --holdout-check off");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("adapts holdout_check 'on', not 'off'"), std::string::npos) << r.err;
  r = test::run(run.command + " --holdout-check maybe");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--holdout-check takes auto, on or off, not 'maybe'"), std::string::npos) << r.err;
}

// Analyser options given to rdsf-adapt reach every step's program (their logs hold the command lines) and
// the adapted model states them (format 4), so rdsf-detect runs it with them; a rerun in the same folder with
// another value is refused before anything is done.
TEST(Adapt, CandidateOptionsReachEveryStepAndTheAdaptedModelStatesThem) {
  test::TempDir dir;
  ASSERT_EQ(render(dir / "room", "--frames 60").exit_code, 0);
  const SmallRoomRun run = small_room_run(dir, 4);
  const std::filesystem::path& models = run.models;
  const std::string command = run.command + " --eval " + test::quote(dir / "room");
  const test::RunResult r = test::run(command + " --hole-gap 20");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* log : {"negatives", "answers", "report"}) {
    EXPECT_NE(test::file_text(dir / ("out/logs/" + std::string(log) + ".log")).find("--hole-gap 20"), std::string::npos)
        << log;
  }
  EXPECT_NE(test::file_text(dir / "out/logs/train.log").find("--detection-options hole_gap=20"), std::string::npos);
  const BoostedModel adapted = BoostedModel::load((models / "room/v1.yml").string());
  EXPECT_EQ(adapted.format_version(), 4);
  const RecordedParameters& stated = adapted.detection_options();
  EXPECT_NE(std::find(stated.begin(), stated.end(), std::make_pair(std::string("hole_gap"), std::string("20"))),
            stated.end());
  const test::RunResult detect = test::run(test::quote(test::program("rdsf-detect")) + " --source " +
                                           test::quote(dir / "room") + " --model " +
                                           test::quote((models / "room/v1.yml").string()) + " --frames 2 --out " +
                                           test::quote(dir / "d.csv"));
  EXPECT_NE(detect.err.find("states its detection options (--hole-gap 20)"), std::string::npos) << detect.err;
  const test::RunResult again = test::run(command + " --hole-gap 30");
  EXPECT_NE(again.exit_code, 0);
  EXPECT_NE(again.err.find("'--hole-gap 20', not '--hole-gap 30'"), std::string::npos) << again.err;
}

TEST(Adapt, RoomWeightBelowOneIsAUsageError) {
  test::TempDir dir;
  const test::RunResult r =
      test::run(adapt() + " --source x --out " + test::quote(dir / "out") + " --name room --room-weight 0");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--room-weight must be at least 1"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(Adapt, AKilledRunResumes) {
  test::TempDir dir;
  ASSERT_EQ(render(dir / "room", "--frames 60").exit_code, 0);
  const SmallRoomRun run = small_room_run(dir, 8);
  const std::filesystem::path& models = run.models;
  const std::string& command = run.command;
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    setpgid(0, 0);  // its own group: the kill reaches the step's program too
    execl("/bin/sh", "sh", "-c", ("exec " + command + " 2>/dev/null").c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  setpgid(pid, pid);
  // Killed once the first step is done (whatever runs then: the questions or the training).
  const std::string state = dir / "out/adapt-state.tsv";
  auto has = [&](const std::string& text) {
    std::ifstream in(state);
    const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return all.find(text) != std::string::npos;
  };
  for (int i = 0; i < 1200 && !has("done.negatives"); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  kill(-pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(has("done.negatives"));
  const test::RunResult r = test::run(command);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("negatives: done before"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(models / "room/v1.yml")) << r.err;
  const AnswerJournal journal(dir / "out/sets/room/labeler-answers.tsv");
  std::set<CandidateKey> keys;
  long human = 0;
  for (const JournalEntry& e : journal.in_force()) {
    EXPECT_TRUE(keys.insert(e.key).second) << "answered twice: " << e.key.frame;
    human += e.by == "human" ? 1 : 0;
  }
  EXPECT_GT(human, 0);
  EXPECT_LE(human, 8);  // the budget over both runs
}

// `dir`/room: 20 frames of a person 25 cm before a wall at 3 m, moving right, and its boxes.csv.
// With `cupboard`, a narrow cupboard stands 25 cm before the wall too, on the right, where nobody goes: not a
// person (the truth names only the one who moves), and like the person a candidate of --local-front only.
void write_room_before_a_wall(const test::TempDir& dir, bool cupboard = false) {
  std::filesystem::create_directories(dir / "room");
  std::ofstream boxes(dir / "room/boxes.csv");
  boxes << "frame,person,x,y,w,h\n";
  for (int i = 0; i < 20; ++i) {
    DepthFrame frame = test::wall_frame(3000);
    const cv::Rect body(200 + 8 * i, 100, 60, 330);
    test::paint(frame, {body.x + 18, body.y, 24, 40}, 2750);  // the head
    test::paint(frame, {body.x, body.y + 40, body.width, body.height - 40}, 2750);
    if (cupboard) test::paint(frame, {540, 120, 70, 310}, 2750);
    char name[16];
    std::snprintf(name, sizeof name, "%06d", i);
    write_png_atomically(dir / (std::string("room/") + name + ".depth.png"), frame.depth_mm);
    boxes << name << ",1," << body.x << "," << body.y << "," << body.width << "," << body.height << "\n";
  }
}

// A room whose person stands 25 cm before a wall (one depth layer with it: no candidate of the defaults)
// and moves along it. Trying the candidate switches, the person (the truth) is asked about what each adds,
// likeliest first; the candidate --local-front adds is the person, so it is taken: every later step runs with
// it and the adapted model states it; the trials' answers count in the budget; the report gives the model as
// given before, then with the switch. --try-switches off tries none (and finds nobody to train on).
TEST(Adapt, ASwitchThatFindsAPersonTheDefaultsMissIsTakenForTheRoom) {
  test::TempDir dir;
  write_room_before_a_wall(dir);
  const SmallRoomRun run = small_room_run(dir, 8);
  const test::RunResult r = test::run(run.command + " --trial-budget 1 --eval " + test::quote(dir / "room"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string state = test::file_text(dir / "out/adapt-state.tsv");
  EXPECT_NE(state.find("switch.local-front\ton"), std::string::npos) << state;
  // The report's before is the model as given (nobody found: no candidate), then with the switch, then after.
  const std::string report = test::file_text(dir / "out/report.txt");
  EXPECT_NE(report.find(": before 0.000 ("), std::string::npos) << report;
  EXPECT_NE(report.find(", with the switches taken (--local-front 70) "), std::string::npos) << report;
  EXPECT_NE(report.find("adapt again with --try-switches off into another --out"), std::string::npos) << report;
  EXPECT_NE(state.find("tar_with_switches\t"), std::string::npos) << state;
  EXPECT_NE(r.err.find("--local-front 70: 1 of 1 answers confirmed a person only it finds: on"), std::string::npos) << r.err;
  EXPECT_NE(test::file_text(dir / "out/logs/switches.log").find("--only-added-by local-front"), std::string::npos);
  EXPECT_NE(test::file_text(dir / "out/logs/answers.log").find("--local-front 70"), std::string::npos);
  const std::regex human("answers.human\t([0-9]+)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(state, m, human)) << state;
  EXPECT_LE(std::stoi(m[1]), 8);
  EXPECT_GE(std::stoi(m[1]), 1);
  EXPECT_TRUE(states_local_front(run.models / "room/v1.yml"));

  const test::RunResult off = test::run(
      replace(replace(run.command, "--name room", "--name plain"), test::quote(dir / "out"), test::quote(dir / "off")) +
      " --try-switches off");
  // Without the switch the room's person has no candidate: nothing to train on (and no base here).
  EXPECT_EQ(off.exit_code, 1) << off.err;
  EXPECT_NE(off.err.find("no positives to train with"), std::string::npos) << off.err;
  EXPECT_EQ(test::file_text(dir / "off/adapt-state.tsv").find("switch."), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "off/logs/switches.log"));
}

// --base-cut: the base rendered here is cut with the detector's defaults (the default), with the options given and
// stated by the model (stated) or with those and the switches the trials took (steps); the room's own samples and
// model have the switch either way. With --base-cache the cuts stand side by side, named by their options; a
// folder resumed with another value is refused.
TEST(Adapt, TheBaseIsCutWithTheDetectorsDefaultsUnlessTold) {
  test::TempDir dir;
  write_room_before_a_wall(dir);
  const SmallRoomRun run = small_room_run(dir, 8);
  const std::filesystem::path cache = dir.path() / "cache";
  const std::string command = replace(run.command, "--base-frames 0", "--base-frames 60 --base-cache " +
                                      test::quote(cache.string())) + " --trial-budget 1 --holdout-check off";
  test::RunResult r = test::run(command);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string state = test::file_text(dir / "out/adapt-state.tsv");
  EXPECT_NE(state.find("switch.local-front\ton"), std::string::npos) << state;
  EXPECT_NE(state.find((cache / "sets-60-defaults/people").string()), std::string::npos) << state;
  EXPECT_FALSE(std::filesystem::exists(cache / "sets-60-local-front-70"));
  EXPECT_TRUE(states_local_front(run.models / "room/v1.yml"));  // the room's model has the switch

  r = test::run(replace(replace(command, test::quote(dir / "out"), test::quote(dir / "steps")), "--name room", "--name room2") +
                " --base-cut steps");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  state = test::file_text(dir / "steps/adapt-state.tsv");
  EXPECT_NE(state.find("switch.local-front\ton"), std::string::npos) << state;
  EXPECT_NE(state.find((cache / "sets-60-local-front-70/people").string()), std::string::npos) << state;
  EXPECT_TRUE(std::filesystem::exists(cache / "sets-60-local-front-70/negatives/manifest.yml"));
  EXPECT_TRUE(states_local_front(run.models / "room2/v1.yml"));

  r = test::run(command + " --base-cut steps");  // the first folder, resumed with another value
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("base_cut 'defaults', not 'steps'"), std::string::npos) << r.err;
  r = test::run(command + " --base-cut all");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--base-cut takes steps, stated or defaults, not 'all'"), std::string::npos) << r.err;
}

// --switch-rule majority: a switch is taken when the person's answers on what it adds confirm more people than
// they reject. Here --local-front adds the person and a cupboard before the same wall: one y, one n, so the
// majority leaves it off where the rule of one person takes it. Each later switch is tried with the switches
// taken before it on; the state pins the rule (a folder resumed with the other rule is refused).
TEST(Adapt, TheMajorityRuleLeavesASwitchOffWhenItAddsAsManyFalseCandidatesAsPeople) {
  test::TempDir dir;
  write_room_before_a_wall(dir, /*cupboard=*/true);
  const SmallRoomRun run = small_room_run(dir, 8);
  const test::RunResult one = test::run(run.command + " --trial-budget 2 --switch-rule one");
  const test::RunResult r = test::run(
      replace(replace(run.command, "--name room", "--name majority"), test::quote(dir / "out"), test::quote(dir / "maj")) +
      " --trial-budget 2 --switch-rule majority");
  EXPECT_NE(one.err.find("--local-front 70: 1 of 2 answers confirmed a person only it finds: on"), std::string::npos)
      << one.err;
  EXPECT_NE(r.err.find("--local-front 70: 1 of 2 answers confirmed a person only it finds, 1 rejected one: off"),
            std::string::npos)
      << r.err;
  const std::string state = test::file_text(dir / "maj/adapt-state.tsv");
  EXPECT_NE(state.find("switch.local-front\toff"), std::string::npos) << state;
  EXPECT_NE(state.find("switch_rule\tmajority"), std::string::npos) << state;
  const test::RunResult other = test::run(
      replace(replace(run.command, "--name room", "--name majority"), test::quote(dir / "out"), test::quote(dir / "maj")) +
      " --trial-budget 2 --switch-rule one");
  EXPECT_NE(other.exit_code, 0);
  EXPECT_NE(other.err.find("switch_rule 'majority', not 'one'"), std::string::npos) << other.err;
  const test::RunResult bad = test::run(run.command + " --switch-rule most");
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_NE(bad.err.find("--switch-rule takes one or majority, not 'most'"), std::string::npos) << bad.err;
}

// With the majority rule a switch taken stays on in the trials after it: the wall room's person is found by
// --local-front alone (one y: taken), and --border-height's trial then runs with the front on.
TEST(Adapt, TheMajorityRuleTriesEachSwitchOnThoseTakenBeforeIt) {
  test::TempDir dir;
  write_room_before_a_wall(dir);
  const SmallRoomRun run = small_room_run(dir, 8);
  const test::RunResult r = test::run(run.command + " --trial-budget 1 --switch-rule majority");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("--local-front 70: 1 of 1 answers confirmed a person only it finds, 0 rejected one: on"),
            std::string::npos)
      << r.err;
  const std::string trials = test::file_text(dir / "out/logs/switches.log");
  const std::size_t border = trials.find("--only-added-by border-height");
  ASSERT_NE(border, std::string::npos) << trials;
  const std::size_t line_start = trials.rfind('\n', border) + 1;
  const std::string command = trials.substr(line_start, trials.find('\n', border) - line_start);
  EXPECT_NE(command.find("--local-front 70"), std::string::npos) << command;
}

// --check-as-given on: with a switch taken, the held-out check also scores the model as given without it on its
// own candidates of the later half. In the wall room the person has no candidate without --local-front, so the
// model without the switch finds nobody there and the switch stays.
TEST(Adapt, TheHoldoutCheckJudgesTheModelWithoutTheSwitchesOnItsOwnCandidates) {
  test::TempDir dir;
  write_room_before_a_wall(dir);
  const SmallRoomRun run = small_room_run(dir, 8);
  const test::RunResult r = test::run(run.command + " --trial-budget 1 --holdout-check on --check-as-given on");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string state = test::file_text(dir / "out/adapt-state.tsv");
  EXPECT_NE(state.find("switch.local-front\ton"), std::string::npos) << state;
  EXPECT_NE(state.find("check_as_given\ton"), std::string::npos) << state;
  EXPECT_NE(r.err.find(" finds 0 without the switches, "), std::string::npos) << r.err;
  EXPECT_EQ(state.find("check\tas given kept"), std::string::npos) << state;
  EXPECT_TRUE(states_local_front(run.models / "room/v1.yml"));
}

// people/v4 states --local-front 70 (and every other option at its default): the room's steps run with the
// front, so the wall room's person has a candidate without any trial; --local-front is not tried (the model
// turns it on), the other switches are, each named once on its trial's command line (a stating model's step
// options name every option: the switch once more was a usage error of rdsf-label).
TEST(Adapt, ASwitchTheModelTurnsOnIsNotTriedTheOthersAre) {
  test::TempDir dir;
  write_room_before_a_wall(dir);
  const SmallRoomRun run = small_room_run(dir, 8, "v4");
  const test::RunResult r = test::run(run.command + " --trial-budget 1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("trying --local-front"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("trying --border-height 25"), std::string::npos) << r.err;
  const std::string state = test::file_text(dir / "out/adapt-state.tsv");
  EXPECT_EQ(state.find("switch.local-front"), std::string::npos) << state;
  EXPECT_NE(state.find("switch.border-height\t"), std::string::npos) << state;
  const std::string trials = test::file_text(dir / "out/logs/switches.log");
  const std::string first_command = trials.substr(0, trials.find('\n'));
  std::size_t named = 0;
  for (std::size_t at = first_command.find("--border-height"); at != std::string::npos;
       at = first_command.find("--border-height", at + 1)) {
    ++named;
  }
  EXPECT_EQ(named, 1u) << first_command;
  EXPECT_NE(test::file_text(dir / "out/logs/answers.log").find("--local-front 70"), std::string::npos);
  EXPECT_TRUE(states_local_front(run.models / "room/v1.yml"));
}
