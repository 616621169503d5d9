// Power loss, full disks and failing I/O (core/durable_io): a labelling session, a mining run and a
// training run with the N-th file call failing, for every N; the same sessions cut by a simulated power
// cut after every call; the miner filling a real small tmpfs. Invariants each time: the run ends with one
// line naming the file and the cause; every sample and model reported as saved is there, intact; no file is
// half-written under a final name; resuming gives the result of an undisturbed run.
#include <gtest/gtest.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include <sys/mount.h>
#include <unistd.h>

#include <opencv2/imgcodecs.hpp>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/core/durable_io.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/dataset/sample_crop.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/frame/depth_png.hpp"
#include "rdsf/labeling/answer_journal.hpp"
#include "support/crash_replay.hpp"
#include "support/depth_scenes.hpp"
#include "support/test_support.hpp"

using namespace rdsf;
namespace fs = std::filesystem;

namespace {

/// Test folders on a RAM disk when there is one: thousands of program runs, each syncing.
void prefer_ram_disk() {
  static const bool done = [] {
    if (::access("/dev/shm", W_OK) == 0) ::setenv("TMPDIR", "/dev/shm", 1);
    return true;
  }();
  (void)done;
}

std::int64_t read_count(const std::string& path) { return std::atoll(test::file_text(path).c_str()); }

/// A sample as the user knows it: label, frame, box (ids and times aside).
using Key = std::tuple<int, std::string, int, int, int, int>;

std::multiset<Key> keys_of(const std::vector<SampleRecord>& records) {
  std::multiset<Key> keys;
  for (const SampleRecord& r : records) {
    keys.insert({r.label, r.frame, r.strict_box.x, r.strict_box.y, r.strict_box.width, r.strict_box.height});
  }
  return keys;
}

/// Every file under `dir` with a final name (not *.tmp, *.partial, hidden, lock) is complete: PNGs decode,
/// manifest.yml and model files parse. Returns the first problem, or "".
std::string half_written_file(const std::string& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) return "";
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir, ec)) {
    if (!e.is_regular_file()) continue;
    const std::string name = e.path().filename().string();
    const std::string path = e.path().string();
    auto ends = [&](const std::string& tail) {
      return name.size() >= tail.size() && name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
    };
    if (name[0] == '.' || ends(".tmp") || ends(".partial") || name == "lock") continue;
    if (ends(".png") && cv::imread(path, cv::IMREAD_UNCHANGED).empty()) return path + ": PNG does not decode";
    if (name == "manifest.yml") {
      try {
        SampleSetManifest::read(path);
      } catch (const Error& err) {
        return err.what();
      }
    }
    if (name.size() > 5 && name[0] == 'v' && ends(".yml")) {
      try {
        BoostedModel::load(path, parent_folder(parent_folder(path)));
      } catch (const Error& err) {
        return err.what();
      }
    }
  }
  return "";
}

/// Opens the set as a writer would (repairing it) and checks that every record's crop is intact and that
/// every id in `saved` is among them. Returns the records, or fails the test.
std::vector<SampleRecord> reopen_and_check(const std::string& dir, const std::set<std::int64_t>& saved,
                                           const std::string& context, bool expect_no_repair_of_rows) {
  std::error_code ec;
  if (!fs::exists(fs::path(dir) / "manifest.yml", ec)) {
    EXPECT_TRUE(saved.empty()) << context << ": samples reported saved but the set has no manifest";
    return {};
  }
  try {
    SampleSetWriter writer = SampleSetWriter::open_existing(dir);
    for (const std::string& repair : writer.repairs()) {
      if (expect_no_repair_of_rows) {
        EXPECT_EQ(repair.find("retracted"), std::string::npos) << context << ": " << repair;
      }
    }
    std::vector<SampleRecord> records = writer.records();
    writer.close();
    const SampleSet set = SampleSet::open_read(dir);
    std::set<std::int64_t> present;
    for (std::size_t i = 0; i < set.records().size(); ++i) {
      const SampleRecord& r = set.records()[i];
      present.insert(r.id);
      if (!r.has_crop) continue;
      const cv::Mat1w crop = set.depth_crop(i);  // throws on a missing, truncated or replaced crop
      EXPECT_EQ(depth_crop_hash(crop), r.crop_hash) << context << ": sample " << r.id;
    }
    for (std::int64_t id : saved) EXPECT_EQ(present.count(id), 1u) << context << ": saved sample " << id << " lost";
    return records;
  } catch (const Error& e) {
    ADD_FAILURE() << context << ": reopening failed: " << e.what();
    return {};
  }
}

/// The labeler's journal: the sample ids it reported saved (answers in force that stored a sample).
std::set<std::int64_t> journal_saved(const std::string& set_dir) {
  std::set<std::int64_t> ids;
  const std::string path = set_dir + "/labeler-answers.tsv";
  std::error_code ec;
  if (!fs::exists(path, ec)) return ids;
  // Read without the journal class (which would repair the file): lines of in-force answers.
  std::ifstream in(path);
  std::map<std::string, std::int64_t> in_force;  // candidate -> sample id
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    if (in.eof()) break;  // a torn last line (no newline) was never acknowledged
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, '\t');) f.push_back(field);
    if (f.size() < 9) continue;
    const std::string candidate = f[1] + '\x1f' + f[2] + '\x1f' + f[3] + ',' + f[4] + ',' + f[5] + ',' + f[6];
    if (f[7] == "u") {
      in_force.erase(candidate);
    } else {
      in_force[candidate] = std::atoll(f[8].c_str());
    }
  }
  // An undo whose retraction was written but not its journal line took effect: the user took it back.
  std::set<std::int64_t> retracted;
  std::ifstream undone(set_dir + "/retracted.tsv");
  std::getline(undone, line);
  while (std::getline(undone, line) && !undone.eof()) retracted.insert(std::atoll(line.c_str()));
  for (const auto& [candidate, id] : in_force) {
    if (id > 0 && retracted.count(id) == 0) ids.insert(id);
  }
  return ids;
}

/// Fault kinds cycled over N: a full disk (stays full), a passing I/O error, a quota hit by a short write.
struct FaultKind {
  const char* spec;
  const char* cause;  ///< strerror text the error line must carry
};
const FaultKind kFaults[] = {{"ENOSPC", "No space left on device"},
                             {"EIO:once", "Input/output error"},
                             {"EDQUOT:short", "Disk quota exceeded"}};

std::string fault_env(std::int64_t n, const FaultKind& kind) {
  std::string spec = kind.spec;
  const std::size_t colon = spec.find(':');
  const std::string error = spec.substr(0, colon);
  const std::string rest = colon == std::string::npos ? "" : spec.substr(colon);
  return "RDSF_IO_FAULT=" + std::to_string(n) + ":" + error + rest;
}

/// The last line of a failed program's stderr: "<program>: <file under root>: ...: <cause>".
void expect_one_line_error(const test::RunResult& r, const std::string& program, const std::string& root,
                           const std::string& cause, const std::string& context) {
  std::string last = r.err;
  while (!last.empty() && last.back() == '\n') last.pop_back();
  last = last.substr(last.rfind('\n') == std::string::npos ? 0 : last.rfind('\n') + 1);
  EXPECT_EQ(last.rfind(program + ": ", 0), 0u) << context << ": " << r.err;
  EXPECT_NE(last.find(root), std::string::npos) << context << ": error names no file: " << last;
  EXPECT_NE(last.find(cause), std::string::npos) << context << ": error names no cause: " << last;
}

/// A labelling session: two frames of three candidates each, every candidate answered 'y' (one undo on the
/// way), so that a resumed session ends where an undisturbed one does.
struct LabelSession {
  test::TempDir dir{"rdsf-durable-label"};
  LabelSession() {
    test::write_two_person_frames(dir / "frames");
    std::ofstream(dir / "keys") << "y y u y y y y y y y y y y y";
  }
  std::string out() const { return dir / "out"; }
  std::string command() const {
    return test::quote(test::program("rdsf-label")) + " --source " + test::quote(dir / "frames") + " --out " +
           test::quote(out() + "/set") + " --answers " + test::quote(dir / "keys");
  }
};

/// A mining run of `frames` people-free synthetic frames with the given extra options.
struct MineRun {
  test::TempDir dir;
  std::string options;
  MineRun(const std::string& tag, int frames, std::string extra) : dir(tag), options(std::move(extra)) {
    const test::RunResult r = test::run(test::quote(test::program("rdsf-synth")) + " --out " +
                                        test::quote(dir / "empty") + " --frames " + std::to_string(frames) +
                                        " --empty --seed 4");
    EXPECT_EQ(r.exit_code, 0) << r.err;
  }
  std::string out() const { return dir / "out"; }
  std::string command() const {
    return test::quote(test::program("rdsf-mine")) + " --source " + test::quote(dir / "empty") + " --out " +
           test::quote(out() + "/set") + options;
  }
};

/// A mining run: one people-free synthetic frame.
struct MineSession : MineRun {
  MineSession() : MineRun("rdsf-durable-mine", 1, "") {}
};

/// A mining run in groups (group commit, MineParams::sync_every_frames): three people-free frames whose
/// samples are flushed two frames at a time.
struct MineGroupSession : MineRun {
  MineGroupSession() : MineRun("rdsf-durable-mine-group", 3, " --sync-every 2 --threads 1") {}
};

cv::Mat1w toy_crop(bool person, int i) {
  cv::Mat1w crop(128, 64, static_cast<std::uint16_t>(3000 + 7 * i));
  if (person) crop(cv::Rect(20, 10, 24, 110)).setTo(1500 + 3 * i);
  return crop;
}

/// A training run: 20 + 20 toy samples, 3 rounds.
struct TrainSession {
  test::TempDir dir{"rdsf-durable-train"};
  TrainSession() {
    for (int label : {1, 0}) {
      SampleSetWriter w = SampleSetWriter::open_or_create(dir / (label ? "pos" : "neg"), FeatureSpec{},
                                                          CameraModel{}, "test");
      for (int i = 0; i < 20; ++i) {
        SampleRecord r;
        r.label = label;
        r.origin = "labeler";
        r.source = "toy";
        r.frame = std::to_string(i);
        r.strict_box = r.window = cv::Rect(i, 0, 10, 20);
        w.append(r, toy_crop(label == 1, i));
      }
    }
  }
  std::string out() const { return dir / "out"; }
  std::string command() const {
    return test::quote(test::program("rdsf-train")) + " --models-dir " + test::quote(out() + "/models") +
           " --pos " + test::quote(dir / "pos") + " --neg " + test::quote(dir / "neg") +
           " --name toy --rounds 3 --threads 1 --group-frames 2";  // 10 validation groups of 2 frames
  }
};

/// What a models folder holds: name/vN -> model file text.
std::map<std::string, std::string> models_in(const std::string& dir) {
  std::map<std::string, std::string> found;
  std::error_code ec;
  if (!fs::exists(dir, ec)) return found;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && name[0] == 'v') found[e.path().parent_path().filename().string() + "/" + name] = "";
  }
  return found;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// The I/O layer itself.

TEST(DurableIo, FaultAtTheNthCallFailsWithTheGivenCauseAndNamesTheFile) {
  prefer_ram_disk();
  test::TempDir dir;
  const std::string path = dir / "a.txt";
  write_file_durably(path, std::string("one\n"));
  EXPECT_EQ(test::file_text(path), "one\n");
  // Calls of a durable write: open, write, fdatasync, close, rename, open folder, fsync, close.
  io::set_fault({});
  write_file_durably(path, std::string("two\n"));
  const std::int64_t calls = io::calls_made();
  EXPECT_EQ(calls, 8);
  for (std::int64_t n = 1; n <= calls; ++n) {
    io::set_fault({n, ENOSPC, false, false});
    try {
      write_file_durably(path, std::string("three\n"));
      ADD_FAILURE() << "call " << n << " failed silently";
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(dir.path().string()), std::string::npos) << what;
      EXPECT_NE(what.find("No space left on device"), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    io::set_fault({});
    // Before the rename the old content stays; after it the new content is complete.
    const std::string now = test::file_text(path);
    EXPECT_TRUE(now == "two\n" || now == "three\n") << n << ": " << now;
    EXPECT_EQ(n <= 5, now == "two\n") << n;
    write_file_durably(path, std::string("two\n"));
  }
  // A short write followed by a full disk.
  io::set_fault({2, EDQUOT, true, false});
  EXPECT_THROW(write_file_durably(path, std::string(1000, 'x')), Error);
  io::set_fault({});
  EXPECT_EQ(test::file_text(path), "two\n");
}

TEST(DurableIo, NewFileUnsyncedNeverOverwritesAndLeavesNothingWhenAWriteFails) {
  prefer_ram_disk();
  test::TempDir dir;
  const std::string path = dir / "crop.png";
  // Calls: open, write, close; no temporary name, no rename, no sync.
  io::set_fault({});
  write_new_file_unsynced(path, std::string("first"));
  EXPECT_EQ(io::calls_made(), 3);
  EXPECT_EQ(test::file_text(path), "first");
  try {
    write_new_file_unsynced(path, std::string("second"));
    ADD_FAILURE() << "an existing file was overwritten";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": already exists"), std::string::npos) << e.what();
  }
  EXPECT_EQ(test::file_text(path), "first");  // untouched
  // A failing write or close removes the new file; a failing open never created it. (The fault passes, as
  // an EIO does: under a fault that fails every later call the removal fails too, and the sample set's
  // reopening removes the crop without a row.)
  for (std::int64_t n = 1; n <= 3; ++n) {
    const std::string other = dir / ("other" + std::to_string(n) + ".png");
    io::set_fault({n, EIO, false, true});
    EXPECT_THROW(write_new_file_unsynced(other, std::string(100, 'x')), Error) << n;
    io::set_fault({});
    EXPECT_FALSE(fs::exists(other)) << "call " << n << " failed and left " << other;
  }
}

TEST(DurableIo, PowerCutModelLosesWhatWasNotSynced) {
  prefer_ram_disk();
  test::TempDir dir;
  const std::string root = dir / "root";
  fs::create_directories(root);
  const std::string record = dir / "record";
  // The layer reads the environment at its first call: the writer is a child process.
  const test::RunResult r = test::run("RDSF_IO_RECORD=" + test::quote(record) + " " +
                                      test::quote(test::program("rdsf-synth")) + " --out " +
                                      test::quote(root + "/synth") + " --frames 2 --seed 1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<test::RecordedCall> calls = test::read_io_record(record);
  ASSERT_GT(calls.size(), 20u);
  // The whole record, nothing lost: the folder as it is.
  test::TempDir whole;
  test::materialize_after_cut(calls, calls.size(), root, test::Loss::unsynced, whole.path().string());
  EXPECT_EQ(test::file_text(whole / "synth/boxes.csv"), test::file_text(root + "/synth/boxes.csv"));
  EXPECT_EQ(test::file_text(whole / "synth/000001.depth.png"), test::file_text(root + "/synth/000001.depth.png"));
  // Before the first folder sync nothing at all survives; an unsynced rename of an unsynced file leaves
  // (data_only) an empty file: the model sees what a careless writer would lose.
  test::TempDir none;
  EXPECT_EQ(test::materialize_after_cut(calls, 1, root, test::Loss::unsynced, none.path().string()), 0u);
  std::vector<test::RecordedCall> careless = {calls[0]};
  careless[0] = {io::Call::open, 50, O_WRONLY | O_CREAT, root + "/x.tmp", "", ""};
  careless.push_back({io::Call::write, 50, 0, "", "", "data"});
  careless.push_back({io::Call::close, 50, 0, "", "", ""});
  careless.push_back({io::Call::rename, -1, 0, root + "/x.tmp", root + "/x", ""});
  test::TempDir lost;
  test::materialize_after_cut(careless, careless.size(), root, test::Loss::data_only, lost.path().string());
  EXPECT_TRUE(fs::exists(lost / "x"));
  EXPECT_EQ(fs::file_size(lost / "x"), 0u);
}

// ---------------------------------------------------------------------------------------------------------
// Faults at every call of a whole session.

namespace {

struct FaultLoopFigures {
  std::int64_t calls = 0, runs = 0, failed_runs = 0;
};

/// Runs `command` with the N-th call failing for N = 1..calls of an undisturbed run, checks the error line
/// and calls `check` (with the run's result) after each, then resumes without fault and compares with the
/// undisturbed run through `final_state`.
template <class Session, class Check, class Final>
FaultLoopFigures fault_every_call(const char* program, Check check, Final final_state) {
  prefer_ram_disk();
  FaultLoopFigures figures;
  Session reference;
  const std::string count_file = reference.dir / "count";
  const test::RunResult clean = test::run("RDSF_IO_COUNT=" + test::quote(count_file) + " " + reference.command());
  EXPECT_EQ(clean.exit_code, 0) << clean.err;
  figures.calls = read_count(count_file);
  EXPECT_GT(figures.calls, 5);
  const auto expected = final_state(reference);
  Session s;
  for (std::int64_t n = 1; n <= figures.calls; ++n) {
    const FaultKind& kind = kFaults[static_cast<std::size_t>(n - 1) % 3];
    const std::string context = std::string(program) + " with call " + std::to_string(n) + " failing (" + kind.spec + ")";
    fs::remove_all(s.out());
    fs::create_directories(s.out());
    const test::RunResult r = test::run(fault_env(n, kind) + " " + s.command());
    ++figures.runs;
    if (r.exit_code != 0) {
      ++figures.failed_runs;
      EXPECT_EQ(r.exit_code, 1) << context << ": " << r.err;
      expect_one_line_error(r, program, s.out(), kind.cause, context);
    }
    check(s, r, context);  // reopens, which repairs
    EXPECT_EQ(half_written_file(s.out()), "") << context;
    // Resumed without a fault, the run ends where an undisturbed one does: nothing lost, nothing twice.
    const test::RunResult resumed = test::run(s.command());
    EXPECT_EQ(resumed.exit_code, 0) << context << ", resumed: " << resumed.err;
    EXPECT_EQ(final_state(s), expected) << context << ", resumed";
    if (::testing::Test::HasFailure()) break;  // one failing N tells enough
  }
  return figures;
}

std::multiset<Key> set_keys(const std::string& dir) {
  std::error_code ec;
  if (!fs::exists(fs::path(dir) / "manifest.yml", ec)) return {};
  return keys_of(SampleSet::open_read(dir).records());
}

}  // namespace

TEST(FaultInjection, LabellingSessionLosesNoSavedAnswerAtAnyFailingCall) {
  const FaultLoopFigures f = fault_every_call<LabelSession>(
      "rdsf-label",
      [](const LabelSession& s, const test::RunResult&, const std::string& context) {
        const std::string set = s.out() + "/set";
        reopen_and_check(set, journal_saved(set), context, true);
      },
      [](const LabelSession& s) { return set_keys(s.out() + "/set"); });
  std::cout << "[figures] rdsf-label: " << f.calls << " fault points, " << f.runs << " runs, " << f.failed_runs
            << " ended in an error\n";
  EXPECT_GT(f.failed_runs, f.calls / 2);
}

TEST(FaultInjection, MiningRunLosesNoSavedSampleAtAnyFailingCall) {
  const FaultLoopFigures f = fault_every_call<MineSession>(
      "rdsf-mine",
      [](const MineSession& s, const test::RunResult&, const std::string& context) {
        // Every row in the index has its crop (rows are written after their crops are on disk).
        const std::string set = s.out() + "/set";
        std::set<std::int64_t> rows;
        std::error_code ec;
        if (fs::exists(set + "/samples.tsv", ec)) {
          std::ifstream in(set + "/samples.tsv");
          std::string line;
          std::getline(in, line);
          while (std::getline(in, line) && !in.eof()) rows.insert(std::atoll(line.c_str()));
        }
        reopen_and_check(set, rows, context, true);
      },
      [](const MineSession& s) { return set_keys(s.out() + "/set"); });
  std::cout << "[figures] rdsf-mine: " << f.calls << " fault points, " << f.runs << " runs, " << f.failed_runs
            << " ended in an error\n";
  EXPECT_GT(f.failed_runs, f.calls / 2);
}

TEST(FaultInjection, TrainingRunLeavesOnlyCompleteModelsAtAnyFailingCall) {
  const FaultLoopFigures f = fault_every_call<TrainSession>(
      "rdsf-train",
      [](const TrainSession& s, const test::RunResult& r, const std::string& context) {
        const std::string wrote = "wrote " + s.out() + "/models/toy/v";
        if (r.err.find(wrote) != std::string::npos || r.out.find(wrote) != std::string::npos) {
          EXPECT_NO_THROW(BoostedModel::load("toy", s.out() + "/models")) << context;
        }
      },
      [](const TrainSession& s) {
        // After the resumed run: exactly one more model, complete (v1 or, when the faulted run saved one, v2).
        return half_written_file(s.out() + "/models").empty() && models_in(s.out() + "/models").count("toy/v1.yml") == 1;
      });
  std::cout << "[figures] rdsf-train: " << f.calls << " fault points, " << f.runs << " runs, " << f.failed_runs
            << " ended in an error\n";
  EXPECT_GT(f.failed_runs, f.calls / 2);
}

// ---------------------------------------------------------------------------------------------------------
// Power cuts after every call.

namespace {

struct CutFigures {
  std::size_t calls = 0, cuts = 0, saved_checked = 0;
};

/// Records a run of `session`, then for every cut point and both loss models materializes the disk and
/// checks the set: every sample whose row was synced before the cut is there with its crop, no row is
/// retracted for a bad crop, no file is half-written under a final name.
template <class Session>
CutFigures cut_everywhere(const std::string& set_name) {
  prefer_ram_disk();
  Session s;
  fs::create_directories(s.out());
  const std::string record = s.dir / "record";
  const test::RunResult r = test::run("RDSF_IO_RECORD=" + test::quote(record) + " " + s.command());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::vector<test::RecordedCall> calls = test::read_io_record(record);
  CutFigures figures;
  figures.calls = calls.size();
  const std::string set_root = fs::absolute(s.out() + "/" + set_name).lexically_normal().string();
  for (std::size_t cut = 0; cut <= calls.size(); ++cut) {
    for (test::Loss loss : {test::Loss::unsynced, test::Loss::data_only}) {
      const std::string context = "power cut after call " + std::to_string(cut) + " of " +
                                  std::to_string(calls.size()) +
                                  (loss == test::Loss::unsynced ? " (unsynced lost)" : " (unsynced data lost)");
      test::TempDir disk{"rdsf-cut"};
      test::materialize_after_cut(calls, cut, s.out(), loss, disk.path().string());
      const std::string set = disk / set_name;
      // Samples acknowledged by then: rows of samples.tsv that were synced (the writer reports a sample
      // saved after that sync), read from the synced bytes.
      std::set<std::int64_t> saved;
      {
        test::TempDir synced{"rdsf-cut-synced"};
        test::materialize_after_cut(calls, cut, s.out(), test::Loss::data_only, synced.path().string());
        std::ifstream in(synced / (set_name + "/samples.tsv"));
        std::string line;
        std::getline(in, line);
        while (std::getline(in, line) && !in.eof()) saved.insert(std::atoll(line.c_str()));
      }
      const std::set<std::int64_t> retracted_by_user = [&] {
        std::set<std::int64_t> ids;
        std::ifstream in(set + "/retracted.tsv");
        std::string line;
        std::getline(in, line);
        while (std::getline(in, line) && !in.eof()) ids.insert(std::atoll(line.c_str()));
        return ids;
      }();
      for (std::int64_t id : retracted_by_user) saved.erase(id);
      reopen_and_check(set, saved, context, true);
      EXPECT_EQ(half_written_file(set), "") << context;
      figures.saved_checked += saved.size();
      ++figures.cuts;
      if (::testing::Test::HasFailure()) return figures;
    }
  }
  return figures;
}

}  // namespace

TEST(PowerCut, LabellingSessionCutAfterEveryCallKeepsEverySavedSample) {
  const CutFigures f = cut_everywhere<LabelSession>("set");
  std::cout << "[figures] rdsf-label: " << f.calls << " calls, " << f.cuts << " simulated power cuts, "
            << f.saved_checked << " saved samples checked, 0 lost\n";
  EXPECT_GT(f.cuts, 100u);
}

TEST(PowerCut, MiningRunCutAfterEveryCallKeepsEverySavedSample) {
  const CutFigures f = cut_everywhere<MineSession>("set");
  std::cout << "[figures] rdsf-mine: " << f.calls << " calls, " << f.cuts << " simulated power cuts, "
            << f.saved_checked << " saved samples checked, 0 lost\n";
  EXPECT_GT(f.cuts, 100u);
}

TEST(PowerCut, MiningInGroupsCutAfterEveryCallKeepsEverySavedSample) {
  const CutFigures f = cut_everywhere<MineGroupSession>("set");
  std::cout << "[figures] rdsf-mine --sync-every 2 (3 frames): " << f.calls << " calls, " << f.cuts
            << " simulated power cuts, " << f.saved_checked << " saved samples checked, 0 lost\n";
  EXPECT_GT(f.cuts, 100u);
  // The rows were flushed in groups: two fdatasyncs of samples.tsv for three frames (frames 1-2, frame 3).
  prefer_ram_disk();
  MineGroupSession s;
  fs::create_directories(s.out());
  const std::string record = s.dir / "record";
  ASSERT_EQ(test::run("RDSF_IO_RECORD=" + test::quote(record) + " " + s.command()).exit_code, 0);
  int row_syncs = 0;
  std::map<int, std::string> open_files;  // fd -> path
  for (const test::RecordedCall& call : test::read_io_record(record)) {
    if (call.call == io::Call::open) open_files[call.fd] = call.path;
    if (call.call == io::Call::fdatasync && open_files[call.fd] == s.out() + "/set/samples.tsv") ++row_syncs;
  }
  EXPECT_EQ(row_syncs, 2);  // frames 1 and 2, then frame 3 (the header was written under a temporary name)
}

TEST(PowerCut, ModelSavedBeforeACutIsComplete) {
  prefer_ram_disk();
  TrainSession s;
  fs::create_directories(s.out());
  const std::string record = s.dir / "record";
  const test::RunResult r = test::run("RDSF_IO_RECORD=" + test::quote(record) + " " + s.command());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<test::RecordedCall> calls = test::read_io_record(record);
  // The model is reported saved once its name is synced: the last folder fsync.
  std::size_t saved_at = calls.size();
  for (std::size_t i = 0; i < calls.size(); ++i) {
    if (calls[i].call == io::Call::link) saved_at = i;
  }
  ASSERT_LT(saved_at, calls.size());
  std::size_t cuts = 0;
  for (std::size_t cut = 0; cut <= calls.size(); ++cut) {
    for (test::Loss loss : {test::Loss::unsynced, test::Loss::data_only}) {
      test::TempDir disk{"rdsf-cut"};
      test::materialize_after_cut(calls, cut, s.out(), loss, disk.path().string());
      EXPECT_EQ(half_written_file(disk / "models"), "") << "cut " << cut;
      if (cut >= saved_at + 4) {  // link, open folder, fsync, close
        EXPECT_NO_THROW(BoostedModel::load("toy", disk / "models")) << "cut " << cut;
      }
      ++cuts;
    }
  }
  std::cout << "[figures] rdsf-train: " << calls.size() << " calls, " << cuts << " simulated power cuts\n";
}

// ---------------------------------------------------------------------------------------------------------
// A real full disk.

TEST(FullDisk, MinerIntoASmallTmpfsStopsWithAClearErrorAndKeepsItsSamples) {
  if (::getuid() != 0) GTEST_SKIP() << "not root: cannot mount a small tmpfs to fill (runs in CI as root)";
  test::TempDir dir{"rdsf-fulldisk"};
  const std::string mount_point = dir / "disk";
  fs::create_directories(mount_point);
  if (::mount("tmpfs", mount_point.c_str(), "tmpfs", 0, "size=160k") != 0) {
    GTEST_SKIP() << "cannot mount a tmpfs here (" << std::strerror(errno) << "): full-disk test skipped";
  }
  struct Unmount {
    std::string path;
    ~Unmount() { ::umount2(path.c_str(), MNT_DETACH); }
  } unmount{mount_point};
  const test::RunResult synth = test::run(test::quote(test::program("rdsf-synth")) + " --out " +
                                          test::quote(dir / "empty") + " --frames 30 --empty --seed 5");
  ASSERT_EQ(synth.exit_code, 0) << synth.err;
  const std::string set = mount_point + "/set";
  const test::RunResult r = test::run(test::quote(test::program("rdsf-mine")) + " --source " +
                                      test::quote(dir / "empty") + " --out " + test::quote(set));
  ASSERT_EQ(r.exit_code, 1) << "the disk did not fill: " << r.err;
  expect_one_line_error(r, "rdsf-mine", mount_point, "No space left on device", "full tmpfs");
  EXPECT_EQ(half_written_file(set), "");
  // Every complete row has its crop; reopening (which repairs) keeps them all.
  std::set<std::int64_t> rows;
  {
    std::ifstream in(set + "/samples.tsv");
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line) && !in.eof()) rows.insert(std::atoll(line.c_str()));
  }
  EXPECT_GT(rows.size(), 10u);
  const std::vector<SampleRecord> records = reopen_and_check(set, rows, "full tmpfs", true);
  EXPECT_EQ(records.size(), rows.size());
  std::cout << "[figures] full tmpfs of 160 KiB: " << rows.size() << " samples saved before the disk filled, 0 lost\n";
}
