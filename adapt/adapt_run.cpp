#include "adapt/adapt_run.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <iostream>
#include <set>

#include <signal.h>
#include <unistd.h>

#include "adapt/adapt_state.hpp"
#include "adapt/holdout_step.hpp"
#include "adapt/run_program.hpp"
#include "cli/cli.hpp"
#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/core/atomic_file.hpp"
#include "rdsf/core/durable_io.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/evaluation/ground_truth.hpp"
#include "rdsf/frame/camera_file.hpp"
#include "rdsf/frame/depth_units.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/frame/png_folder_source.hpp"
#include "rdsf/labeling/answer_journal.hpp"
#include "rdsf/pipeline/candidate_switches.hpp"
#include "rdsf/pipeline/holdout_check.hpp"
#include "rdsf/pipeline/room_presence.hpp"

namespace rdsf {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Paths {
  std::string negatives, room, logs, base, root;
  std::string check;  ///< the held-out check's folder (its earlier-half sets and trial model)
  explicit Paths(const std::string& out)
      : negatives((fs::path(out) / "sets" / "room-negatives").string()),
        room((fs::path(out) / "sets" / "room").string()),
        logs((fs::path(out) / "logs").string()),
        base((fs::path(out) / "base").string()),
        root(out),
        check((fs::path(out) / "check").string()) {}
  /// The sample set of the trial of a candidate switch (its option's name).
  std::string trial(const std::string& option) const { return (fs::path(root) / "sets" / ("trial-" + option)).string(); }
  std::string base_part(const std::string& part) const { return (fs::path(base) / part).string(); }
  std::string log(const std::string& step) const { return (fs::path(logs) / (step + ".log")).string(); }
};

void say(const std::string& line) { std::cerr << "rdsf-adapt: " << line << "\n"; }

// Runs a sibling program; a failure is one line: the program's own last line and where the log is.
void run_step_program(const std::string& program, const std::vector<std::string>& args, const std::string& log) {
  const int code = run_program(sibling_program(program), args, log);
  if (code == 0) return;
  const std::vector<std::string> last = log_lines(log, program + ": ", 1);
  throw Error(program + " failed (exit " + std::to_string(code) + "): " +
              (last.empty() ? std::string("see ") + log : last.back() + " (log: " + log + ")"));
}

// The room's frames as PNG frames: without a recording of the room empty, the frames taken as empty are
// mined from the room's own frames, by file (write_empty_frames). Throws Error naming `path` otherwise.
const PngFolderSource& room_pngs(const FrameSource& frames, const std::string& path) {
  const auto* pngs = dynamic_cast<const PngFolderSource*>(&frames);
  if (pngs == nullptr) {
    fail(path, "without a recording of the room empty, the frames taken as empty are mined from the room's "
               "own frames, which must then be PNG frames (a folder or a list file)");
  }
  return *pngs;
}

// The room's depth must be millimetres of a Kinect-class camera, at any resolution (each source carries its
// camera model, by which every step cuts its crops: docs/sensors.md, "Any resolution"), and truth must name
// only frames of the room (source or eval). Checked before anything is written.
void check_room(const AdaptOptions& o, const BoostedModel& model) {
  std::set<std::string> names;
  const std::pair<std::string, bool> specs[] = {{o.source, true}, {o.eval, true}, {o.empty, false}};
  for (const auto& [spec, named_by_truth] : specs) {  // named_by_truth: --truth may name its frames
    if (spec.empty()) continue;
    auto frames = open_frame_source(spec);
    if (spec == o.source && o.empty.empty()) room_pngs(*frames, spec);
    DepthFrame frame;
    if (!frames->next(frame)) fail(spec, "no frames");
    const int median = median_reading_mm(frame.depth_mm);  // the first frame's
    if (!plausible_median_reading_mm(median)) {
      fail(spec, "depth values (median " + std::to_string(median) + ") are not millimetres of a Kinect-class camera "
                 "like the crops of " + model_reference(model));
    }
    if (o.truth.empty() || !named_by_truth) continue;  // the truth names frames of the source or eval
    if (const auto known = frames->frame_names()) {    // files: their names without decoding every frame
      names.insert(known->begin(), known->end());
      continue;
    }
    names.insert(frame.name);
    while (frames->next(frame)) names.insert(frame.name);
  }
  if (o.truth.empty()) return;
  const GroundTruth truth = read_ground_truth(o.truth);
  for (const auto& [frame, people] : truth.frames) {
    if (!people.empty() && names.count(frame) == 0) {
      fail(o.truth, "frame '" + frame + "' is not in " + o.source + (o.eval.empty() ? "" : " nor " + o.eval));
    }
  }
}

// The analyser options every step runs with: the ones given, the model's stated ones for the rest.
struct StepOptions {
  AnalyserParams analyser;
  /// For the steps' programs: every option whose value differs from the default or that the model states
  /// (a program given --model would take the model's value for an option not on its command line).
  std::vector<std::string> arguments;
  /// What the adapted model is told to state (--detection-options of rdsf-train): none when no option was
  /// given (nor --thesis) and the model states none; rdsf-train then states what the sample sets record.
  RecordedParameters stated;
};

// Whether `options` hold the analyser option of `key` (parameter_key: "hole_gap").
bool holds(const RecordedParameters& options, const std::string& key) {
  return std::any_of(options.begin(), options.end(), [&](const auto& option) { return option.first == key; });
}

StepOptions step_options(const AdaptOptions& o, const BoostedModel& model) {
  StepOptions s;
  s.analyser = o.given.for_model(o.analyser, &model);
  const RecordedParameters all = stated_options(s.analyser), departures = departures_from_defaults(all);
  RecordedParameters passed;
  for (const auto& option : all) {
    if (holds(model.detection_options(), option.first) ||
        std::find(departures.begin(), departures.end(), option) != departures.end()) {
      passed.push_back(option);
    }
  }
  s.arguments = cli::analyser_arguments(passed);
  if (!o.given.keys.empty() || !o.given.take_stated || !model.detection_options().empty()) s.stated = all;
  return s;
}

// The room presence scan's pipeline: the steps' analyser options as they are.
PipelineParams presence_params(const StepOptions& step) {
  PipelineParams p;
  p.analyser = step.analyser;
  p.analyser_given.take_stated = false;
  return p;
}

// `args` with the steps' analyser options after them.
std::vector<std::string> with_options(std::vector<std::string> args, const StepOptions& s) {
  args.insert(args.end(), s.arguments.begin(), s.arguments.end());
  return args;
}

// A list file of the room's frames taken as empty (absolute paths), for rdsf-mine.
// A list file's frames take the camera.yml of the list's folder (png_folder_source.hpp), so the room's own
// camera.yml (its camera model and depth unit) is written beside the list, in a folder of their own.
std::string write_empty_frames(const AdaptOptions& o, const RoomPresence& presence) {
  std::map<std::string, std::string> path_of;  // frame name -> depth PNG
  const std::unique_ptr<FrameSource> source = open_frame_source(o.source);
  const PngFolderSource& pngs = room_pngs(*source, o.source);
  for (const std::string& path : pngs.depth_paths()) {  // its list file read by the library
    path_of[PngFolderSource::frame_name(path)] = fs::absolute(path).string();
  }
  const fs::path dir = fs::path(o.out) / "empty-frames";
  fs::create_directories(dir);
  const fs::path camera_path = dir / CameraFile::kFileName;
  if (pngs.camera_file()) {
    write_file_durably(camera_path.string(), camera_file_text(*pngs.camera_file()));
  } else {
    fs::remove(camera_path);  // the Kinect v1's model scaled to the frames, as for the room
  }
  const std::string list = (dir / "frames.txt").string();
  AtomicTextFile file(list, /*overwrite=*/true);
  for (std::size_t f = 0; f < presence.frames.size(); ++f) {
    if (presence.empty[f] == 0) continue;
    const auto it = path_of.find(presence.frames[f]);
    if (it == path_of.end()) fail(o.source, "frame '" + presence.frames[f] + "': its file is not known");
    file.stream() << it->second << "\n";
  }
  file.commit();
  return list;
}

// An --empty recording with people in it is refused before anything is written: the model, with the
// tracker, follows one person over PresenceParams::confident_track_frames frames (docs/adapting-to-your-room.md).
// With --trust-empty (the user has looked at the frame named: nobody is there) it is used all the same: what
// the model follows there is then the room's strongest false positive, its hardest negative.
void check_empty_recording(const AdaptOptions& o, const BoostedModel& model, const StepOptions& step) {
  if (o.empty.empty()) return;
  const RoomPresence presence = scan_room_presence(o.empty, model, presence_params(step), CameraModel::kinect_v1());
  const PresenceParams& rule = presence.rule;
  if (presence.longest_confident_track >= rule.confident_track_frames) {
    const std::string seen = model_reference(model) + " follows a person over " +
                             std::to_string(presence.longest_confident_track) + " frames with P(person) >= " +
                             std::to_string(rule.confident_probability).substr(0, 4) + " (up to frame " +
                             presence.confident_track_end + ")";
    if (!o.trust_empty) {
      fail(o.empty, "not empty: " + seen + "; give a recording without people, or none, or --trust-empty when "
                    "nobody is in that frame");
    }
    say(o.empty + ": taken as empty (--trust-empty) although " + seen + ": its false positives are mined first");
    return;
  }
  say(o.empty + ": nobody followed over " + std::to_string(rule.confident_track_frames) + " frames (longest " +
      std::to_string(presence.longest_confident_track) + ")");
}

// Step 0, without base sets: the small synthetic base (docs/adapting-to-your-room.md, "The base"): rdsf-synth's
// seed 11, --base-frames frames of 1-4 people in rooms of 15 frames and half as many of the same rooms empty, the
// furniture without dropout holes (as the shipped model's training since people/v3); its people labelled from the
// generator's truth (no question asked) and its empty frames mined, both with the analyser options `step`
// (--base-cut: the detector's defaults unless told). The same options give the same sets. The frames as frames-N
// and empty-N (N frames with people; a change of this recipe must rename them, or old caches would be reused) in
// OUT/base, or with --base-cache in that folder, and the sets as OUT/base/{people,negatives} or in the cache as
// sets-N-OPTIONS/{people,negatives} (OPTIONS: the options' departures from the defaults, e.g.
// local-front-70_border-height-25, or "defaults"), each made once under a temporary name and renamed into place,
// so that a folder under its name is whole and runs sharing the cache reuse it.
struct BaseSets {
  std::string people, negatives;
};

// `folder`, made by `make` into a temporary name beside it (FOLDER.part-PID) and renamed into place, unless it is
// there. What a killed run left under such a name (its process gone) is removed first.
void make_folder_once(const std::string& folder, const std::function<void(const std::string&)>& make) {
  if (fs::exists(folder)) return;
  const fs::path parent = fs::path(folder).parent_path();
  fs::create_directories(parent);
  const std::string prefix = fs::path(folder).filename().string() + ".part-";
  for (const fs::directory_entry& entry : fs::directory_iterator(parent)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
    if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) fs::remove_all(entry.path());
  }
  const std::string part = folder + ".part-" + std::to_string(::getpid());
  fs::remove_all(part);
  make(part);
  std::error_code error;
  fs::rename(part, folder, error);
  if (!error) return;
  fs::remove_all(part);  // another run sharing the cache made it first
  if (!fs::exists(folder)) throw Error(folder + ": cannot rename " + part + " into place: " + error.message());
}

// The analyser options' departures from the defaults as a folder name's part: "local-front-70_border-height-25".
std::string options_name(const StepOptions& step) {
  std::string name;
  for (const auto& [key, text] : departures_from_defaults(stated_options(step.analyser))) {
    std::string word = key + "-" + text;
    for (char& c : word) c = std::isalnum(static_cast<unsigned char>(c)) || c == '.' ? c : '-';
    name += (name.empty() ? "" : "_") + word;
  }
  return name.empty() ? "defaults" : name;
}

BaseSets render_base(const AdaptOptions& o, const StepOptions& step, const Paths& paths) {
  const std::string count = std::to_string(o.base_frames), empty_count = std::to_string(std::max(1, o.base_frames / 2));
  const fs::path dir = o.base_cache.empty() ? fs::path(paths.base) : fs::path(o.base_cache);
  // The frames' folder names are the same in both places: rdsf-train's validation groups are named by the folder a
  // sample's frame came from (sample_groups.hpp), so that a run with a cache and one without train the same model.
  const std::string frames = (dir / ("frames-" + count)).string(), empty = (dir / ("empty-" + count)).string();
  const std::string cut_with = options_name(step);
  const fs::path sets = o.base_cache.empty() ? dir : dir / ("sets-" + count + "-" + cut_with);
  const BaseSets out{(sets / "people").string(), (sets / "negatives").string()};
  const std::vector<std::string> scene{"--people", "1..4", "--seed", "11", "--clip-frames", "15",
                                       "--furniture-dropout", "0", "--force"};
  const auto render = [&](const std::string& folder, std::vector<std::string> args, const std::string& what) {
    make_folder_once(folder, [&](const std::string& part) {
      say("base: rendering " + what + " into " + folder + " (rdsf-synth; progress in " + paths.log("base") + ")");
      args.insert(args.begin(), {"--out", part});
      args.insert(args.end(), scene.begin(), scene.end());
      run_step_program("rdsf-synth", args, paths.log("base"));
    });
  };
  render(frames, {"--frames", count}, count + " frames with people");
  render(empty, {"--frames", empty_count, "--empty"}, empty_count + " frames of the same rooms empty");
  const auto cut = [&](const std::string& set, const std::string& program, std::vector<std::string> args) {
    make_folder_once(set, [&](const std::string& part) {
      args.insert(args.end(), {"--out", part, "--threads", std::to_string(o.threads)});
      run_step_program(program, with_options(args, step), paths.log("base"));
    });
  };
  say("base: its sets cut with " + (cut_with == "defaults" ? "the detector's default options" : "the options " + cut_with) +
      " (people labelled from the generator's truth by rdsf-label, empty frames mined by rdsf-mine; about 50 s in all "
      "for 600 frames on 2 cores; reused when there)");
  cut(out.people, "rdsf-label",
      {"--source", frames, "--truth", (fs::path(frames) / "boxes.csv").string(), "--answers", "/dev/null",
       "--keep-rejected"});
  cut(out.negatives, "rdsf-mine", {"--source", empty});
  say("a synthetic base rendered in " + dir.string() + ": " + out.people + " and " + out.negatives + " (" + count +
      " frames with people, " + empty_count + " empty)");
  return out;
}

// Step 1: the room's negatives, the model's false positives first.
void room_negatives(const AdaptOptions& o, const BoostedModel& model, const StepOptions& step, AdaptState& state,
                    const Paths& paths) {
  std::string source = o.empty;  // checked by check_empty_recording
  if (o.empty.empty()) {
    const RoomPresence presence = scan_room_presence(o.source, model, presence_params(step), CameraModel::kinect_v1());
    say(std::to_string(presence.empty_frames()) + " of " + std::to_string(presence.frames.size()) +
        " frames taken as empty (no candidate with P >= 0.2 within 15 frames, runs of 10 frames or more)");
    if (!o.truth.empty()) {  // how often that took a person as empty
      const GroundTruth truth = read_ground_truth(o.truth);
      long with_people = 0, people = 0;
      for (std::size_t f = 0; f < presence.frames.size(); ++f) {
        if (presence.empty[f] == 0) continue;
        const std::size_t n = truth.in(presence.frames[f]).size();
        with_people += n > 0 ? 1 : 0;
        people += static_cast<long>(n);
      }
      say("truth: " + std::to_string(with_people) + " of the frames taken as empty have people (" +
          std::to_string(people) + " boxes)");
      state.set("empty.frames_with_people", std::to_string(with_people));
    }
    state.set("empty.frames", std::to_string(presence.empty_frames()));
    if (presence.empty_frames() == 0) return;
    source = write_empty_frames(o, presence);
  }
  char min_score[32];
  std::snprintf(min_score, sizeof min_score, "%.6g", model.calibration().score_at(0.5));
  const std::vector<std::string> common =
      with_options({"--source", source, "--out", paths.negatives, "--threads", std::to_string(o.threads)}, step);
  std::vector<std::string> hard = common;  // the model's false positives first, then every other candidate
  hard.insert(hard.end(), {"--model", o.model, "--models-dir", o.models_dir, "--min-score", min_score});
  run_step_program("rdsf-mine", hard, paths.log("negatives"));
  run_step_program("rdsf-mine", common, paths.log("negatives"));
  state.set("negatives", paths.negatives);
}

struct Answers {
  long human = 0, propagated = 0;  ///< the person's answers, and the labels their tracks and places gave
  long human_people = 0;           ///< of the person's answers, the y
  long human_others = 0;           ///< ... and the n
  long by_model_track = 0;         ///< labels along the model's own sure answers' tracks (no person's answer)
};

Answers count_answers(const std::string& room_set) {
  Answers a;
  const fs::path journal = fs::path(room_set) / "labeler-answers.tsv";
  if (!fs::exists(journal)) return a;
  const AnswerJournal answers(journal.string());
  for (const JournalEntry& e : answers.in_force()) {
    a.human += e.by == "human" ? 1 : 0;
    a.human_people += e.by == "human" && e.answer == 'y' ? 1 : 0;
    a.human_others += e.by == "human" && e.answer == 'n' ? 1 : 0;
    a.propagated += e.by.rfind("track ", 0) == 0 || e.by.rfind("place ", 0) == 0 ? 1 : 0;
    a.by_model_track += e.by.rfind("model-track ", 0) == 0 ? 1 : 0;
  }
  return a;
}

// The switches a room may try: not given, not turned on by the model (a model states every option, most at
// their defaults: people/v4 states local_front 70 and every other switch off), not under --thesis.
std::vector<CandidateSwitch> switches_to_try(const AdaptOptions& o, const BoostedModel& model) {
  std::vector<CandidateSwitch> out;
  if (!o.try_switches || !o.given.take_stated) return out;
  const RecordedParameters turned = departures_from_defaults(model.detection_options());
  for (const CandidateSwitch& sw : candidate_switches()) {
    const std::string key = parameter_key(sw.option);
    const bool given = std::find(o.given.keys.begin(), o.given.keys.end(), key) != o.given.keys.end();
    if (!given && !holds(turned, key)) out.push_back(sw);
  }
  return out;
}

// `o` with switch `sw` on, as if given on the command line (a model's stated value of it is not taken).
AdaptOptions with_switch(AdaptOptions o, const CandidateSwitch& sw) {
  const Parameter<AnalyserParams>& row = *find_parameter(analyser_parameters(), sw.option);
  row.set(o.analyser, parameter_value_of_text(sw.on, row.get(o.analyser), row.name));
  o.given.keys.push_back(parameter_key(sw.option));
  return o;
}

// Whether a trial's answers take its switch (AdaptOptions::switch_majority).
bool takes_switch(const AdaptOptions& o, const Answers& a) {
  return o.switch_majority ? a.human_people > a.human_others : a.human_people > 0;
}

// Step "switches": each switch tried in the room; its state row says on or off, answers.trials the answers.
void try_switches(const AdaptOptions& o, const BoostedModel& model, AdaptState& state, const Paths& paths) {
  if (state.done("base") || state.done("negatives") || state.done("answers")) {  // a folder begun before trials
    say("switches: not tried: this folder's later steps ran before (their samples were cut without trials)");
    return;
  }
  long spent = 0;
  const long most = o.budget / 2;  // the trials never take more than half the budget: the room's questions come
  AdaptOptions before = o;         // the options a trial adds its switch to: with the majority rule, those taken
  for (const CandidateSwitch& sw : switches_to_try(o, model)) {
    const std::string set = paths.trial(sw.option);
    const long left = std::min<long>(o.trial_budget, most - spent) - count_answers(set).human;
    if (left > 0) {
      say("trying --" + sw.option + " " + sw.on + " (" + sw.finds + "): are the candidates only it adds people? (at "
          "most " + std::to_string(left) + " answers, likeliest first)");
      std::vector<std::string> args{"--source", o.source, "--out", set, "--model", o.model, "--models-dir",
                                    o.models_dir, "--ask", "likely", "--no-model-answers", "--per-track",
                                    "--per-place", o.per_place ? "on" : "off", "--keep-rejected", "--budget",
                                    std::to_string(left), "--only-added-by", sw.option, "--threads",
                                    std::to_string(o.threads)};
      if (!o.truth.empty()) args.insert(args.end(), {"--truth", o.truth, "--truth-oracle"});
      if (!o.answers.empty()) args.insert(args.end(), {"--answers", o.answers});
      args = with_options(args, step_options(with_switch(before, sw), model));  // the switch on, once among them
      const bool window = o.truth.empty() && o.answers.empty();
      run_step_program("rdsf-label", args, window ? std::string() : paths.log("switches"));
    }
    const Answers a = count_answers(set);  // the person's own y decide, not the labels their tracks gave
    spent += a.human;
    const bool take = takes_switch(o, a);
    state.set("switch." + sw.option, take ? "on" : "off");
    if (take && o.switch_majority) before = with_switch(std::move(before), sw);
    say("--" + sw.option + " " + sw.on + ": " + std::to_string(a.human_people) + " of " + std::to_string(a.human) +
        " answers confirmed a person only it finds" +
        (o.switch_majority ? ", " + std::to_string(a.human_others) + " rejected one" : std::string()) + ": " +
        (take ? "on" : "off"));
  }
  state.set("answers.trials", std::to_string(spent));
}

// The switches the trials took (the state's switch.NAME rows), in candidate_switches() order.
std::vector<CandidateSwitch> switches_taken(const AdaptState& state) {
  std::vector<CandidateSwitch> out;
  for (const CandidateSwitch& sw : candidate_switches()) {
    if (state.get("switch." + sw.option) == "on") out.push_back(sw);
  }
  return out;
}

// The held-out check found the model as given better without the switches than with them and than the trial.
bool switches_dropped(const AdaptState& state) { return state.get("check") == "as given kept"; }

// The options after the switches' trials: those taken given as if on the command line (every later step runs
// with them and the adapted model states them).
AdaptOptions with_switches_taken(const AdaptOptions& o, const AdaptState& state) {
  AdaptOptions taken = o;
  for (const CandidateSwitch& sw : switches_taken(state)) taken = with_switch(std::move(taken), sw);
  return taken;
}

// Step 2: the person answers what the model is unsure of, one answer per track, within the budget.
void room_answers(const AdaptOptions& o, const StepOptions& step, AdaptState& state, const Paths& paths) {
  const long trials = std::atol(state.get("answers.trials").c_str());
  const long left = o.budget - trials - count_answers(paths.room).human;  // a resumed run spends only the rest
  if (left > 0) {
    std::vector<std::string> args{"--source", o.source, "--out", paths.room, "--model", o.model, "--models-dir",
                                  o.models_dir, "--ask", "uncertain", "--keep-rejected", "--budget",
                                  std::to_string(left), "--threads", std::to_string(o.threads)};
    if (!o.per_candidate) args.insert(args.end(), {"--per-track", "--per-place", o.per_place ? "on" : "off"});
    if (!o.per_candidate) args.insert(args.end(), {"--propagate-model-answers", o.propagate_model ? "on" : "off"});
    if (!o.truth.empty()) args.insert(args.end(), {"--truth", o.truth, "--truth-oracle"});
    if (!o.answers.empty()) args.insert(args.end(), {"--answers", o.answers});
    const bool window = o.truth.empty() && o.answers.empty();
    run_step_program("rdsf-label", with_options(args, step), window ? std::string() : paths.log("answers"));
  }
  const Answers a = count_answers(paths.room);
  state.set("answers.human", std::to_string(a.human + trials));  // every answer the person gave
  state.set("answers.propagated", std::to_string(a.propagated));
  state.set("answers.model_track", std::to_string(a.by_model_track));
  say(std::to_string(a.human) + " answers given (and " + std::to_string(trials) + " in the switches' trials), " +
      std::to_string(a.propagated) +
      " labels propagated along their tracks, " + std::to_string(a.by_model_track) +
      " along the tracks of the model's sure answers");
}

// What a room's model records of how it was made, beside rdsf-train's own record.
RecordedParameters room_provenance(const AdaptOptions& o, const BoostedModel& model, const AdaptState& state) {
  std::string base;
  for (const std::string& s : o.base_pos) base += (base.empty() ? "" : " ") + s;
  for (const std::string& s : o.base_neg) base += (base.empty() ? "" : " ") + s;
  return {{kAdaptedRoomParameter, fs::absolute(o.source).string()},
          {"adapted_from", model_reference(model)},
          {"adapted_answers", state.get("answers.human") + " human, " + state.get("answers.propagated") +
                                  " propagated, " + state.get("answers.model_track") + " along the model's tracks"},
          {"adapted_base", base.empty() ? std::string("none") : base}};
}

// The room's sample sets (its answers, and those of the switches taken: each holds the person's y that took it).
std::vector<std::string> room_sets(const AdaptState& state, const Paths& paths) {
  std::vector<std::string> sets{paths.room};
  for (const CandidateSwitch& sw : switches_taken(state)) sets.push_back(paths.trial(sw.option));
  return sets;
}

// rdsf-train of the room's sets (`sets`; `negatives`, the room's mined negatives, or empty) with the base sets,
// saved as models_dir/name/vN: the path it wrote and the seconds it took.
std::pair<std::string, std::string> train_with_base(const AdaptOptions& o, const BoostedModel& model,
                                                    const StepOptions& step, const AdaptState& state,
                                                    const std::vector<std::string>& sets, const std::string& negatives,
                                                    const std::string& models_dir, const std::string& name,
                                                    const std::string& log) {
  // A set given K times puts each of its samples K times among the rows: weight K, each copy in the validation
  // group of its frame. Without a base there is nothing to weigh against, and validation then splits samples,
  // not frames (below), which would put copies on both sides: the room's sets once.
  const bool no_base = o.base_pos.empty() && o.base_neg.empty();
  const int copies = no_base ? 1 : o.room_weight;
  std::vector<std::string> args{"--models-dir", models_dir, "--name", name, "--pos"};
  for (int k = 0; k < copies; ++k) args.insert(args.end(), sets.begin(), sets.end());
  args.insert(args.end(), o.base_pos.begin(), o.base_pos.end());
  args.push_back("--neg");
  for (int k = 0; k < copies; ++k) {
    if (!negatives.empty()) args.push_back(negatives);
    args.insert(args.end(), sets.begin(), sets.end());
  }
  args.insert(args.end(), o.base_neg.begin(), o.base_neg.end());
  const int rounds = o.rounds > 0 ? o.rounds : o.retrain ? 100 : kContinuedRounds;
  // One held-out fifth for validation and calibration (--folds 0): K fold models would cost K trainings.
  args.insert(args.end(), {"--rounds", std::to_string(rounds), "--folds", "0"});
  // The model as given: as the user named it when the room's model is saved beside it (the model file records
  // that text), by its path from the check's own models folder.
  if (!o.retrain) args.insert(args.end(), {"--init", models_dir == o.models_dir ? o.model : model.path()});
  // The room's model states no operating point and is read at P >= 0.5 of its own calibration, whatever its
  // base states: choosing its point by the base's rule (--operating-tar 0.8 for people/v3) on its one held-out
  // fifth lowered MOTA at the point in 11 of the benchmark's 30 adapted rows and raised it in 3 (mean 0.669 ->
  // 0.609; docs/adapting-to-your-room.md, "The adapted model's operating point").
  // Without a base, one room's few samples cannot be split by groups of frames: validation takes samples.
  if (no_base) args.insert(args.end(), {"--group-frames", "0"});
  for (const auto& [key, value] : room_provenance(o, model, state)) args.insert(args.end(), {"--provenance", key + "=" + value});
  if (!step.stated.empty()) {  // the options the room's samples were cut with, which the model then runs with
    args.push_back("--detection-options");
    const RecordedParameters departures = departures_from_defaults(step.stated);
    for (const auto& [key, text] : departures) args.push_back(key + "=" + text);
    if (departures.empty()) args.push_back("defaults");
  }
  const auto t0 = Clock::now();
  run_step_program("rdsf-train", args, log);
  const std::vector<std::string> wrote = log_lines(log, "rdsf-train: wrote ", 1);
  if (wrote.empty()) throw Error(log + ": rdsf-train did not say which file it wrote");
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.1f", std::chrono::duration<double>(Clock::now() - t0).count());
  return {wrote.back().substr(std::string("rdsf-train: wrote ").size()), seconds};
}

// Step 2b (--holdout-check): the trial trained as the room's model is, into the check's own folder; with switches
// taken, the model as given with `tried`'s options (without them) is judged too.
void check_room_model(const AdaptOptions& o, const BoostedModel& model, const StepOptions& step,
                      const StepOptions& tried, AdaptState& state, const Paths& paths) {
  HoldoutInputs in;
  if (o.check_as_given && !switches_taken(state).empty()) in.as_given = tried.analyser;
  in.source = o.source;
  in.room_sets = room_sets(state, paths);
  if (!state.get("negatives").empty()) in.negatives = paths.negatives;
  in.negatives_from_room = o.empty.empty();
  in.dir = paths.check;
  in.log = paths.log("check");
  const std::string models = (fs::path(paths.check) / "models").string();
  run_holdout_check(in, model, state, [&](const std::vector<std::string>& sets, const std::string& negatives) {
    return train_with_base(o, model, step, state, sets, negatives, models, "trial", in.log);
  });
}

// Step 3: the room's samples with the base sets; the new model's path goes to the state. After a held-out check
// the base won, the room's model is the model as given, stating `step`'s options (the switches taken, or none when
// the check dropped them) with no round added.
void train_room_model(const AdaptOptions& o, const BoostedModel& model, const StepOptions& step, AdaptState& state,
                      const Paths& paths) {
  if (state.get("check") == "base kept" || switches_dropped(state)) {
    RecordedParameters provenance = room_provenance(o, model, state);
    provenance.emplace_back("adapted_check", "the model as given kept: " + state.get("check.figures"));
    BoostedModel kept = base_as_room_model(model, step.stated, provenance);
    const std::string path = save_new_model_version(kept, o.name, o.models_dir);
    state.set("model", path);
    state.set("train_seconds", "0.0");
    say("kept " + model_reference(model) + " as " + path + " (the held-out check: no round added)");
    return;
  }
  const auto [path, seconds] = train_with_base(o, model, step, state, room_sets(state, paths),
                                               state.get("negatives").empty() ? std::string() : paths.negatives,
                                               o.models_dir, o.name, paths.log("train"));
  state.set("model", path);
  state.set("train_seconds", seconds);
  say("trained " + path + " in " + seconds + " s (" + (o.retrain ? "from nothing" : "continuing " + o.model) + ")");
}

// TAR at FPPF <= 0.1 of the base model and of the adapted one on the eval frames, and the adapted minus the
// base with its 95 % interval paired over the frames' clips: one rdsf-detect run of both models (its
// summary.txt holds each model's exact-curve line in order, then the paired differences).
// Frames per clip of the held-out frames' paired interval: about 3 s of a 30 fps recording.
constexpr int kEvalClipFrames = 100;

struct BeforeAfter {
  std::string before, after;
  std::string difference;  ///< "+0.083 (+0.000 to +0.167 over 3 clips) few", or "... (one clip: no interval)"
};
// rdsf-detect of `models` on the eval frames with `step`'s options, its report in `dir`; its summary.txt.
std::string evaluate(const AdaptOptions& o, const StepOptions& step, const std::vector<std::string>& models,
                     const std::string& dir, const Paths& paths) {
  std::vector<std::string> args{"--source", o.eval, "--truth", o.truth, "--models-dir", o.models_dir};
  for (const std::string& m : models) args.insert(args.end(), {"--model", m});
  args.insert(args.end(), {"--clip-frames", std::to_string(kEvalClipFrames), "--report-dir", dir, "--force"});
  run_step_program("rdsf-detect", with_options(args, step), paths.log("report"));
  return (fs::path(dir) / "summary.txt").string();
}

// What a summary.txt says: each model's TAR at FPPF <= 0.1 (its exact-curve line, in model order) and, with
// two models, the paired difference's text.
struct SummaryFigures {
  std::vector<std::string> tars;
  std::string difference;
};
SummaryFigures read_summary(const std::string& summary) {
  std::ifstream in(summary);
  SummaryFigures f;
  const std::string curve = "exact curve: TAR ", paired = ": TAR at FPPF <= 0.1 ";
  for (std::string line; std::getline(in, line);) {
    const std::size_t at = line.find(curve);
    if (at != std::string::npos) {
      f.tars.push_back(line.substr(at + curve.size(), line.find(' ', at + curve.size()) - at - curve.size()));
    }
    const std::size_t d = line.find(paired);
    if (d != std::string::npos && line.rfind(' ', 0) == 0) {
      f.difference = line.substr(d + paired.size(), line.find(';', d) - d - paired.size());
    }
  }
  return f;
}

BeforeAfter compare_on_eval(const AdaptOptions& o, const StepOptions& step, const std::string& adapted,
                            const std::string& dir, const Paths& paths) {
  const std::string summary = evaluate(o, step, {o.model, adapted}, dir, paths);
  const SummaryFigures f = read_summary(summary);
  if (f.tars.size() != 2 || f.difference.empty()) fail(summary, "no TAR at FPPF <= 0.1 of both models in it");
  return {f.tars[0], f.tars[1], f.difference};
}

// TAR at FPPF <= 0.1 of the model as given (without the switches its trials took) on the eval frames.
std::string tar_as_given(const AdaptOptions& o, const StepOptions& tried, const std::string& dir, const Paths& paths) {
  const std::string summary = evaluate(o, tried, {o.model}, dir, paths);
  const SummaryFigures f = read_summary(summary);
  if (f.tars.size() != 1) fail(summary, "no TAR at FPPF <= 0.1 in it");
  return f.tars[0];
}

// Step 4: before / after on held-out frames, else the answers and the new model's own validation. With switches
// taken, "before" is the model as given (`tried`'s options) and the paired comparison is with the switches.
void report(const AdaptOptions& o, const StepOptions& tried, const StepOptions& step, AdaptState& state,
            const Paths& paths) {
  const BoostedModel adapted = BoostedModel::load(state.get("model"));
  const RocSummary& v = adapted.training().validation.summary;
  const std::string trained =
      state.get("check") == "base kept"       ? "no round trained (the model as given, kept by the held-out check)"
      : switches_dropped(state) ? "no round trained (the model as given, without the switches, kept by the held-out check)"
                                : "trained in " + state.get("train_seconds") + " s";
  char line[400];
  std::snprintf(line, sizeof line,
                "%s: %s answers, %s labels propagated (%s more along the model's tracks), %s; validation "
                "AUC %.4f, TAR %.3f at FAR 1%%",
                state.get("model").c_str(), state.get("answers.human").c_str(), state.get("answers.propagated").c_str(),
                state.get("answers.model_track").c_str(), trained.c_str(), v.auc, v.tar_at_far_1);
  std::string text = std::string(line) + "\n";
  if (!state.get("check.figures").empty()) {
    text += "held-out check (the trial trained in " + state.get("check_train_seconds") + " s): " +
            state.get("check.figures") + ": " + state.get("check") + "\n";
  }
  RecordedParameters switched;  // the switches the trials took, unless the check dropped them
  if (!switches_dropped(state)) {
    for (const CandidateSwitch& sw : switches_taken(state)) switched.emplace_back(parameter_key(sw.option), sw.on);
  }
  const std::string taken = option_words(switched);
  if (!taken.empty()) {  // what the switches can cost (docs/adapting-to-your-room.md, "A room of close people")
    text += "the room's model states the switches its trials took (" + taken + "); in a few rooms of people close "
            "to the camera switches cost people the model as given found: to compare, adapt again with "
            "--try-switches off into another --out and --name, and run rdsf-detect --truth on frames you labelled "
            "with both models\n";
  }
  if (!o.truth.empty() && !o.eval.empty()) {
    const BeforeAfter b = compare_on_eval(o, step, state.get("model"), (fs::path(o.out) / "report").string(), paths);
    state.set("tar_after", b.after);
    state.set("tar_difference", b.difference);
    if (taken.empty()) {
      state.set("tar_before", b.before);
      text += "TAR at FPPF <= 0.1 on " + o.eval + ": before " + b.before + " (" + o.model + "), after " + b.after +
              "; after - before " + b.difference + ", paired over the frames' clips of " +
              std::to_string(kEvalClipFrames) + "\n";
    } else {
      const std::string before = tar_as_given(o, tried, (fs::path(o.out) / "report-as-given").string(), paths);
      state.set("tar_before", before);
      state.set("tar_with_switches", b.before);
      text += "TAR at FPPF <= 0.1 on " + o.eval + ": before " + before + " (" + o.model + "), with the switches taken (" +
              taken + ") " + b.before + ", after " + b.after + "; after - with the switches " + b.difference +
              ", paired over the frames' clips of " + std::to_string(kEvalClipFrames) + "\n";
    }
  }
  AtomicTextFile file((fs::path(o.out) / "report.txt").string(), /*overwrite=*/true);
  file.stream() << text;
  file.commit();
  std::cerr << text;
}

// --holdout-check, auto resolved by the base's size (kHoldoutCheckMaxBaseSamples).
bool holdout_check_on(const AdaptOptions& o) {
  if (o.holdout_check) return *o.holdout_check;
  std::set<std::string> sets(o.base_pos.begin(), o.base_pos.end());
  sets.insert(o.base_neg.begin(), o.base_neg.end());
  std::size_t samples = 0;
  for (const std::string& set : sets) {  // a set that is not there is rdsf-train's to refuse, with its message
    if (fs::exists(fs::path(set) / "manifest.yml")) samples += SampleSet::open_read(set).records().size();
  }
  return samples > 0 && samples <= kHoldoutCheckMaxBaseSamples;
}

void step(AdaptState& state, const std::string& name, const std::function<void()>& work) {
  if (state.done(name)) {
    say(name + ": done before (" + state.path() + ")");
    return;
  }
  say(name + " ...");
  work();
  state.mark_done(name);
}

}  // namespace

int run_adapt(const AdaptOptions& given) {
  const BoostedModel model = BoostedModel::load(given.model, given.models_dir);
  const StepOptions tried = step_options(given, model);
  check_room(given, model);  // bad input is refused before anything is written
  check_empty_recording(given, model, tried);
  AdaptState state(given.out);
  state.pin("room", fs::absolute(given.source).string());
  state.pin("name", given.name);
  state.pin("analyser_options", option_words(departures_from_defaults(stated_options(tried.analyser))));
  state.pin("try_switches", given.try_switches ? "on" : "off");
  state.pin("switch_rule", given.switch_majority ? "majority" : "one");
  state.pin("holdout_check", !given.holdout_check ? "auto" : *given.holdout_check ? "on" : "off");
  state.pin("check_as_given", given.check_as_given ? "on" : "off");
  state.pin("base_cut", AdaptOptions::base_cut_name(given.base_cut));
  const Paths paths(given.out);
  fs::create_directories(paths.logs);
  step(state, "switches", [&] { try_switches(given, model, state, paths); });
  const AdaptOptions o = with_switches_taken(given, state);
  const StepOptions options = step_options(o, model);
  AdaptOptions with_base = o;
  if (o.base_pos.empty() && o.base_neg.empty() && o.base_frames > 0) {
    step(state, "base", [&] {
      const StepOptions defaults;  // the detector's own: no option given, none taken from a model
      const BaseSets base = render_base(o,
                                        o.base_cut == AdaptOptions::BaseCut::steps    ? options
                                        : o.base_cut == AdaptOptions::BaseCut::stated ? tried
                                                                                      : defaults,
                                        paths);
      state.set("base.people", base.people);
      state.set("base.negatives", base.negatives);
    });
    const std::string people = state.get("base.people"), negatives = state.get("base.negatives");  // none before
    with_base.base_pos = {people.empty() ? paths.base_part("people") : people};                  // 2026-12-08
    with_base.base_neg = {negatives.empty() ? paths.base_part("negatives") : negatives};
  }
  step(state, "negatives", [&] { room_negatives(o, model, options, state, paths); });
  step(state, "answers", [&] { room_answers(o, options, state, paths); });
  if (holdout_check_on(with_base)) {
    step(state, "check", [&] { check_room_model(with_base, model, options, tried, state, paths); });
  }
  const StepOptions& room = switches_dropped(state) ? tried : options;  // the options the room's model states
  step(state, "train", [&] { train_room_model(with_base, model, room, state, paths); });
  step(state, "report", [&] { report(o, tried, room, state, paths); });
  return 0;
}

}  // namespace rdsf
