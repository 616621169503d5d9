#include "perf_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include <sys/resource.h>
#include <unistd.h>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/classifier/binned_matrix.hpp"
#include "rdsf/classifier/boost_training.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/classifier/opencv_boost.hpp"
#include "rdsf/classifier/real_adaboost.hpp"
#include "rdsf/classifier/roc_metrics.hpp"
#include "cli/cli.hpp"
#include "cli/progress.hpp"
#include "rdsf/core/clock.hpp"
#include "rdsf/core/utc_time.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/dataset/negative_miner.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/frame/depth_png.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/labeling/labeling_session.hpp"
#include "rdsf/pipeline/parallel_pipeline.hpp"
#include "rdsf/pipeline/stated_options.hpp"
#include "memory_peak.hpp"
#include "report_clock.hpp"
#include "speed_limits.hpp"
#include "training_crops.hpp"
#include "rdsf/synth/synth_sequence.hpp"
#include "rdsf/synth/synth_writer.hpp"

namespace fs = std::filesystem;

namespace rdsf::perf {
namespace {

using clock::Clock;
using clock::seconds_since;
const auto cpu_seconds = clock::process_cpu_seconds;  // the whole process, every thread

void say(const std::string& text) { std::cerr << "rdsf-perf-report: " << text << std::endl; }

std::string first_line_value(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(key, 0) != 0) continue;
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string value = line.substr(colon + 1);
    value.erase(0, value.find_first_not_of(" \t"));
    return value;
  }
  return {};
}

/// Records a phase's memory: construct at its start, call done() at its end.
class MemoryPhase {
 public:
  MemoryPhase(PerfResults& r, std::string name) : r_(r), name_(std::move(name)), mark_(start_memory_phase()) {}
  void done() { r_.memory.push_back({name_, mark_.rss_mib, peak_rss_mib(), mark_.reset}); }

 private:
  PerfResults& r_;
  std::string name_;
  MemoryMark mark_;
};

synth::SynthParams sequence_params(const PerfOptions& o, int frames, std::uint64_t seed, bool empty) {
  synth::SynthParams p = synth::people_scene(frames, 1, 4, seed);
  p.empty = empty;
  p.rgb = true;
  p.clip_frames = o.quick ? 12 : 60;
  return p;
}

/// The whole system through the library's parallel pipeline (run_in_frame_order: frames analysed on
/// `threads` threads, tracking in frame order): each frame's per-candidate person ids, and the wall time.
template <typename Run>
double run_whole_system(const PipelineParams& params, const BoostedModel& model, Run&& run,
                        std::vector<std::vector<int>>& person) {
  PeoplePipeline pipeline(params, &model);
  person.clear();
  const Clock::time_point start = Clock::now();
  run(pipeline, [&](const DepthFrame&, PipelineFrame& out) {
    person.push_back(out.person);
    return true;
  });
  return seconds_since(start);
}

double validation_auc(const std::vector<WeakClassifier>& weak, std::size_t rounds, const BinScheme& bins,
                      const TrainingRows& validation) {
  std::vector<double> scores(validation.labels.size(), 0.0);
  for (std::size_t k = 0; k < std::min(rounds, weak.size()); ++k) {
    for (std::size_t i = 0; i < scores.size(); ++i) {
      scores[i] += weak[k].respond(validation.rows(static_cast<int>(i), weak[k].feature), bins);
    }
  }
  return roc_auc(scores, validation.labels);
}

// ---- phases ----

struct Workspace {
  fs::path root;
  bool remove = false;
  ~Workspace() {
    if (!remove) return;
    std::error_code ec;
    fs::remove_all(root, ec);
  }
};

void machine(PerfResults& r, const PerfOptions& o) {
  r.date_utc = rdsf::utc_now("%Y-%m-%d %H:%M UTC");
  r.mode = o.quick ? "quick" : "full";
  r.cpu_model = first_line_value("/proc/cpuinfo", "model name");
  if (r.cpu_model.empty()) r.cpu_model = "unknown";
  r.cores = static_cast<int>(std::thread::hardware_concurrency());
  const std::string mem = first_line_value("/proc/meminfo", "MemTotal");
  r.memory_gib = mem.empty() ? 0.0 : std::stod(mem) / (1024.0 * 1024.0);
  r.load_start = clock::load_average_now();
  r.reference_start_ms = clock::reference_loop_ms();
  r.reference_start_gbps = read_bandwidth_gbps(256, 1, 3);
  r.threads = o.threads;
}

std::vector<DepthFrame> render_people(PerfResults& r, const PerfOptions& o, const fs::path& folder) {
  MemoryPhase memory(r, "render and write synthetic frames");
  const synth::SynthParams params = sequence_params(o, o.frames, 101, false);
  r.frames = o.frames;
  r.people_min = params.people_min;
  r.people_max = params.people_max;
  r.width_px = params.width_px;
  r.height_px = params.height_px;
  synth::SynthSequence sequence(params);
  synth::prepare_output_folder(folder.string(), false);
  synth::SynthWriter writer(folder.string(), params, false);
  std::vector<DepthFrame> frames;
  say("rendering " + std::to_string(o.frames) + " frames 640x480 with 1..4 people (kept in memory, written to " +
      folder.string() + ")");
  cli::Progress progress(std::cerr, "frames", o.frames);
  double render_s = 0;
  for (int i = 0; i < o.frames; ++i) {
    const Clock::time_point t = Clock::now();
    const synth::SynthFrame f = sequence.frame(i);
    render_s += seconds_since(t);
    writer.write(f);
    frames.push_back(f.depth_frame(params.camera()));
    progress.update(i + 1);
  }
  progress.finish(o.frames);
  writer.commit("rdsf-perf-report");
  r.render_ms_per_frame = 1000.0 * render_s / o.frames;
  double bytes = 0;
  for (const DepthFrame& f : frames) {
    bytes += static_cast<double>(f.depth_mm.total() * f.depth_mm.elemSize() + f.bgr.total() * f.bgr.elemSize());
  }
  r.frames_mib = bytes / (1024.0 * 1024.0);

  const synth::SynthParams empty = sequence_params(o, o.empty_frames, 303, true);
  const fs::path empty_folder = folder.parent_path() / "empty";
  synth::SynthSequence rooms(empty);
  synth::prepare_output_folder(empty_folder.string(), false);
  synth::SynthWriter empty_writer(empty_folder.string(), empty, false);
  say("rendering " + std::to_string(o.empty_frames) + " people-free frames for mining");
  cli::Progress empty_progress(std::cerr, "frames", o.empty_frames);
  for (int i = 0; i < o.empty_frames; ++i) {
    empty_writer.write(rooms.frame(i));
    empty_progress.update(i + 1);
  }
  empty_progress.finish(o.empty_frames);
  empty_writer.commit("rdsf-perf-report");
  memory.done();
  return frames;
}

BoostedModel train_pipeline_model(PerfResults& r, const PerfOptions& o) {
  MemoryPhase memory(r, "train the pipeline's model (synthetic candidates)");
  const synth::SynthParams params = sequence_params(o, o.train_frames, 202, false);
  synth::SynthSequence sequence(params);
  const FrameAnalyser analyser;
  cv::Mat1f rows;
  std::vector<int> labels;
  say("labelling the candidates of " + std::to_string(o.train_frames) +
      " other synthetic frames by their overlap with the true boxes");
  cli::Progress progress(std::cerr, "frames", o.train_frames);
  for (int i = 0; i < o.train_frames; ++i) {
    const synth::SynthFrame f = sequence.frame(i);
    const FrameAnalysis analysis = analyser.analyse(f.depth_frame(params.camera()), true);
    for (std::size_t c = 0; c < analysis.candidates.size(); ++c) {
      double best = 0.0;
      for (const synth::PersonTruth& p : f.people) best = std::max(best, iou(analysis.candidates[c].strict_box, p.box));
      if (best >= 0.3 && best < 0.5) continue;  // uncertain: left out, as the assisted labeller asks about it
      rows.push_back(analysis.features.row(static_cast<int>(c)));
      labels.push_back(best >= 0.5 ? 1 : 0);
    }
    progress.update(i + 1);
  }
  progress.finish(o.train_frames);
  r.train_frames = o.train_frames;
  r.train_positives = static_cast<int>(std::count(labels.begin(), labels.end(), 1));
  r.train_negatives = static_cast<int>(std::count(labels.begin(), labels.end(), 0));
  if (r.train_positives < 4 || r.train_negatives < 4) {
    throw Error("too few training candidates (" + std::to_string(r.train_positives) + " people, " +
                std::to_string(r.train_negatives) + " others): use more --train-frames");
  }
  BoostTrainingParams tp;
  tp.rounds = o.model_rounds;
  tp.bins.count = 16;
  const Clock::time_point start = Clock::now();
  BoostedModel model = train_boosted_model(rows, labels, tp);
  r.model_train_s = seconds_since(start);
  r.model_rounds = static_cast<int>(model.weak_classifiers().size());
  r.model_validation_auc = model.training().validation.summary.auc;
  say("model: " + std::to_string(r.train_positives) + " people, " + std::to_string(r.train_negatives) +
      " others, " + std::to_string(r.model_rounds) + " rounds, validation AUC " +
      std::to_string(r.model_validation_auc));
  memory.done();
  return model;
}

// The median of `walls` (seconds) and its extremes; returns the index of the median pass.
std::size_t median_pass(const std::vector<double>& walls, double& median, double& fastest, double& slowest) {
  std::vector<std::size_t> order(walls.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return walls[a] < walls[b]; });
  const std::size_t middle = order[order.size() / 2];
  median = walls[middle];
  fastest = walls[order.front()];
  slowest = walls[order.back()];
  return middle;
}

/// `passes` runs of the whole system on one thread over `frames` (a fresh pipeline each): the wall time of
/// each pass's process() calls and its stage times; pass 0's person ids and counts.
struct OneThreadPasses {
  std::vector<double> walls;
  std::vector<StageTimes> stages;
  std::vector<std::vector<int>> person;  ///< pass 0's, per frame
  long long candidates = 0, detections = 0;
  int people_tracked = 0;
};

OneThreadPasses one_thread_passes(const PipelineParams& params, const BoostedModel& model,
                                  const std::vector<DepthFrame>& frames, int passes) {
  OneThreadPasses out;
  cli::Progress progress(std::cerr, "frames", static_cast<std::int64_t>(frames.size()) * passes);
  std::int64_t done = 0;
  for (int pass = 0; pass < passes; ++pass) {
    PeoplePipeline pipeline(params, &model);
    double wall = 0;
    StageTimes stage;
    for (const DepthFrame& frame : frames) {
      const Clock::time_point t = Clock::now();
      const PipelineFrame result = pipeline.process(frame);
      wall += seconds_since(t);
      stage += result.times;
      if (pass == 0) {
        out.candidates += static_cast<long long>(result.analysis.candidates.size());
        out.detections += std::count_if(result.person.begin(), result.person.end(), [](int id) { return id != 0; });
        out.person.push_back(result.person);
      }
      progress.update(++done);
    }
    out.walls.push_back(wall);
    out.stages.push_back(stage);
    out.people_tracked = static_cast<int>(pipeline.tracker().people().size());
  }
  progress.finish(static_cast<std::int64_t>(frames.size()) * passes);
  return out;
}

/// `passes` runs of the whole system on `threads` threads (frames analysed in parallel, tracking in order):
/// each pass's wall time; `identical` says whether every pass gave `reference`'s person ids.
std::vector<double> parallel_passes(const PipelineParams& params, const BoostedModel& model,
                                    const std::vector<DepthFrame>& frames, int threads, int passes,
                                    const std::vector<std::vector<int>>& reference, bool& identical) {
  std::vector<double> walls;
  identical = true;
  for (int pass = 0; pass < passes; ++pass) {
    std::vector<std::vector<int>> person;
    walls.push_back(run_whole_system(params, model, [&](PeoplePipeline& pipeline, const PipelineCallback& on_frame) {
      run_in_frame_order(pipeline, static_cast<std::int64_t>(frames.size()),
                         [&](std::int64_t i) { return frames[static_cast<std::size_t>(i)]; }, {threads, 0}, on_frame);
    }, person));
    identical = identical && person == reference;
  }
  return walls;
}

std::vector<std::vector<int>> whole_system_one_thread(PerfResults& r, const PerfOptions& o,
                                                      const std::vector<DepthFrame>& frames, const BoostedModel& model) {
  MemoryPhase memory(r, "whole system, 1 thread (frames in memory)");
  r.whole_passes = o.quick ? 1 : 5;
  say("whole system on 1 thread (PeoplePipeline: segmentation, candidates, RDSF, classifier, tracking), " +
      std::to_string(r.whole_passes) + " passes");
  OneThreadPasses run = one_thread_passes(PipelineParams{}, model, frames, r.whole_passes);
  r.candidates = run.candidates;
  r.detections = run.detections;
  r.people_tracked = run.people_tracked;
  r.stage_ms = run.stages[median_pass(run.walls, r.pipeline_wall_s, r.pipeline_wall_min_s, r.pipeline_wall_max_s)];
  memory.done();
  return std::move(run.person);
}

void whole_system_parallel(PerfResults& r, const PerfOptions& o, const std::vector<DepthFrame>& frames,
                           const BoostedModel& model, const std::vector<std::vector<int>>& reference) {
  MemoryPhase memory(r, "whole system, " + std::to_string(o.threads) + " threads (frames in memory)");
  say("whole system on " + std::to_string(o.threads) + " threads (frames analysed in parallel, tracking in order), " +
      std::to_string(r.whole_passes) + " passes");
  const std::vector<double> walls =
      parallel_passes(PipelineParams{}, model, frames, o.threads, r.whole_passes, reference, r.parallel_identical);
  median_pass(walls, r.parallel_wall_s, r.parallel_wall_min_s, r.parallel_wall_max_s);
  memory.done();
}

// The shipped default model as a detector runs it (its stated options taken, read at its operating point),
// on the same frames: what a lab's `rdsf-detect` without --model costs, beside the rows of this run's own
// model, which states nothing.
void shipped_default_model(PerfResults& r, const PerfOptions& o, const std::vector<DepthFrame>& frames) {
  MemoryPhase memory(r, "the shipped default model, 1 and " + std::to_string(o.threads) + " threads");
  const BoostedModel model = BoostedModel::load(resolve_model(kDefaultModelName));
  PerfResults::ShippedRun& s = r.shipped;
  s.model = model_label(model);
  s.options = option_words(departures_from_defaults(model.detection_options()));
  s.rounds = static_cast<int>(model.weak_classifiers().size());
  say("the shipped default model " + s.model + (s.options.empty() ? "" : " with " + s.options) + " on 1 and " +
      std::to_string(o.threads) + " threads, " + std::to_string(r.whole_passes) + " passes each");
  const OneThreadPasses run = one_thread_passes(PipelineParams{}, model, frames, r.whole_passes);
  s.candidates = run.candidates;
  s.detections = run.detections;
  s.stage_ms = run.stages[median_pass(run.walls, s.wall_s, s.wall_min_s, s.wall_max_s)];
  const std::vector<double> walls =
      parallel_passes(PipelineParams{}, model, frames, o.threads, r.whole_passes, run.person, s.parallel_identical);
  median_pass(walls, s.parallel_wall_s, s.parallel_wall_min_s, s.parallel_wall_max_s);
  memory.done();
}

void live_mode(PerfResults& r, const PerfOptions& o, const std::vector<DepthFrame>& frames, const BoostedModel& model) {
  MemoryPhase memory(r, "live mode (frames in memory at 30 and 90 fps)");
  for (const double fps : {30.0, 90.0}) {
    const int count = std::min(static_cast<int>(frames.size()), static_cast<int>(fps * (o.quick ? 1 : 3)));
    say("live mode: " + std::to_string(count) + " frames pushed at " + std::to_string(static_cast<int>(fps)) +
        " fps to " + std::to_string(o.threads) + " workers");
    PeoplePipeline pipeline(PipelineParams{}, &model);
    const SteadyClock clock;
    LivePipeline live(pipeline, {o.threads}, clock, {});
    const auto period = std::chrono::duration<double>(1.0 / fps);
    const Clock::time_point start = Clock::now();
    for (int i = 0; i < count; ++i) {
      std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(period * i));
      live.push(frames[static_cast<std::size_t>(i)]);
    }
    live.finish();
    r.live.push_back({fps, live.stats()});
  }
  memory.done();
}

void png_reading(PerfResults& r, const PerfOptions& o, const fs::path& folder, const BoostedModel& model,
                 const std::vector<std::vector<int>>& reference) {
  MemoryPhase memory(r, "PNG reading and whole system from files");
  say("reading the frames back from PNG files (depth + colour)");
  const CameraModel camera = CameraModel::kinect_v1();
  auto source = open_frame_source(folder.string(), camera);
  DepthFrame frame;
  int count = 0;
  const Clock::time_point start = Clock::now();
  while (source->next(frame)) ++count;
  r.png_read_ms_per_frame = count > 0 ? 1000.0 * seconds_since(start) / count : 0.0;

  say("whole system from the PNG files on " + std::to_string(o.threads) + " threads");
  std::vector<std::vector<int>> person;
  r.files_parallel_wall_s = run_whole_system(PipelineParams{}, model, [&](PeoplePipeline& pipeline, const PipelineCallback& on_frame) {
    auto files = open_frame_source(folder.string(), camera);  // decoded on the workers
    run_in_frame_order(pipeline, *files, camera, {o.threads, 0}, on_frame);
  }, person);
  if (person != reference) say("warning: the frames read from PNG gave other results than those in memory");
  memory.done();
}

void training_per_round(PerfResults& r, const PerfOptions& o) {
  MemoryPhase memory(r, "training comparison (native and OpenCV)");
  say("training rows: " + std::to_string(o.positives) + " + " + std::to_string(o.negatives) +
      " generated crops and their RDSF (plus 20 % as validation)");
  const Clock::time_point gen = Clock::now();
  const TrainingRows train = make_training_rows(o.positives, o.negatives, 1);
  const TrainingRows validation = make_training_rows(o.positives / 5, o.negatives / 5, 2);
  r.rows_generate_s = seconds_since(gen);
  r.train_rows_positive = o.positives;
  r.train_rows_negative = o.negatives;
  r.validation_rows = validation.rows.rows;
  r.dimension = train.rows.cols;

  say("native Real AdaBoost: " + std::to_string(o.native_rounds) + " rounds on " + std::to_string(o.threads) +
      " threads");
  const BinnedRows binned = bin_positives_first(train, o.threads);
  r.native_binning_s = binned.seconds;
  const BinScheme& bins = binned.matrix.scheme();
  RealAdaBoostParams params;
  params.threads = o.threads;
  RealAdaBoost booster(binned.matrix, binned.labels, params);
  const Clock::time_point rounds_start = Clock::now();
  const double rounds_cpu = cpu_seconds();
  for (int k = 0; k < o.native_rounds; ++k) booster.next_round();
  r.native_s_per_round = seconds_since(rounds_start) / o.native_rounds;
  r.native_cpu_s_per_round = (cpu_seconds() - rounds_cpu) / o.native_rounds;
  r.native_rounds = o.native_rounds;
  const std::vector<WeakClassifier>& native = booster.weak_classifiers();
  r.native_auc_final = validation_auc(native, native.size(), bins, validation);

  int a = 0, b = 0;
  if (std::sscanf(o.opencv_rounds.c_str(), "%d,%d", &a, &b) == 2 && a > 0 && b > a) {
    r.opencv_ran = true;
    r.opencv_a = a;
    r.opencv_b = b;
    OpenCvBoostParams cv_params;
    say("OpenCV cv::ml::Boost REAL stumps: " + std::to_string(a) + " round(s), then " + std::to_string(b) +
        " rounds (one call each, timed whole)");
    cv_params.rounds = a;
    Clock::time_point t = Clock::now();
    double cpu = cpu_seconds();
    train_opencv_boost(train.rows, train.labels, cv_params);
    r.opencv_a_s = seconds_since(t);
    const double cpu_a = cpu_seconds() - cpu;
    say("  " + std::to_string(a) + " round(s): " + std::to_string(r.opencv_a_s) + " s");
    cv_params.rounds = b;
    t = Clock::now();
    cpu = cpu_seconds();
    const OpenCvBoostResult result = train_opencv_boost(train.rows, train.labels, cv_params);
    r.opencv_b_s = seconds_since(t);
    r.opencv_cpu_s_per_round = (cpu_seconds() - cpu - cpu_a) / (b - a);
    say("  " + std::to_string(b) + " rounds: " + std::to_string(r.opencv_b_s) + " s");
    r.opencv_s_per_round = (r.opencv_b_s - r.opencv_a_s) / (b - a);
    r.opencv_setup_s = std::max(0.0, r.opencv_a_s - r.opencv_s_per_round * a);
    r.opencv_auc_at_b = validation_auc(result.stumps, static_cast<std::size_t>(b), bins, validation);
    r.native_auc_at_b = validation_auc(native, static_cast<std::size_t>(b), bins, validation);
    for (std::size_t k = 1; k <= native.size(); ++k) {
      if (validation_auc(native, k, bins, validation) >= r.opencv_auc_at_b) {
        r.native_rounds_to_opencv_auc = static_cast<int>(k);
        break;
      }
    }
  }
  memory.done();
}

void mining(PerfResults& r, const PerfOptions& o, const fs::path& work) {
  MemoryPhase memory(r, "mining negatives (" + std::to_string(o.threads) + " threads)");
  say("mining negatives from " + std::to_string(o.empty_frames) + " people-free PNG frames on " +
      std::to_string(o.threads) + " threads, " + (o.quick ? "once" : "3 times") +
      " into the scratch folder and into memory, alternated");
  MineParams params;
  params.sources = {(work / "empty").string()};
  params.threads = o.threads;
  params.camera = CameraModel::kinect_v1();
  // Mines into a new set at `set` and returns the wall time.
  const auto mine_into = [&](const fs::path& set) {
    SampleSetWriter out = SampleSetWriter::open_or_create(set.string(), FeatureSpec{}, params.camera, "rdsf-perf-report");
    cli::Progress progress(std::cerr, "frames", o.empty_frames);
    const Clock::time_point start = Clock::now();
    const MineStats stats = mine_negatives(params, out, [&](const MineStats& s) { progress.update(s.frames); });
    const double wall = seconds_since(start);
    progress.finish(stats.frames);
    r.mined_frames = stats.frames;
    r.mined_candidates = stats.candidates;
    r.mined_kept = stats.kept;
    return wall;
  };
  r.mining_passes = o.quick ? 1 : 3;
  std::error_code ec;
  const bool have_memory = fs::is_directory("/dev/shm", ec);
  std::vector<double> disk_walls, memory_walls;
  for (int pass = 1; pass <= r.mining_passes; ++pass) {
    disk_walls.push_back(mine_into(work / ("mined-" + std::to_string(pass))));
    if (!have_memory) continue;
    const fs::path in_memory = fs::path("/dev/shm") / ("rdsf-perf-report-mined-" + std::to_string(::getpid()));
    say("mining the same frames into a set in memory (" + in_memory.string() + ")");
    memory_walls.push_back(mine_into(in_memory));
    fs::remove_all(in_memory, ec);
  }
  median_pass(disk_walls, r.mining_wall_s, r.mining_wall_min_s, r.mining_wall_max_s);
  if (have_memory) median_pass(memory_walls, r.mining_memory_wall_s, r.mining_memory_wall_min_s, r.mining_memory_wall_max_s);
  memory.done();
}

void labelling(PerfResults& r, const PerfOptions& o, const fs::path& work, const BoostedModel& model) {
  MemoryPhase memory(r, "labelling session (headless)");
  say("labelling headless: " + std::to_string(o.answers) +
      " answers given at once, each timed from answer() to current() returning the next candidate");
  LabelingConfig config;
  config.sources = {(work / "people").string()};
  config.camera = CameraModel::kinect_v1();
  config.model_answers = false;  // every candidate is asked (the labeller measured before model answers)
  SampleSetWriter out =
      SampleSetWriter::open_or_create((work / "labelled").string(), FeatureSpec{}, config.camera, "rdsf-perf-report");
  LabelingSession session(config, out, &model, nullptr);
  std::vector<double> latency_ms;
  const PresentedCandidate* current = session.current();
  while (current != nullptr && static_cast<int>(latency_ms.size()) < o.answers) {
    const LoadedFrame* frame = current->frame.get();
    const char key = current->frame->scores[current->index] >= 0.0 ? 'y' : 'n';  // the model's suggestion
    const Clock::time_point t = Clock::now();
    session.answer(key);
    current = session.current();
    latency_ms.push_back(1000.0 * seconds_since(t));
    if (current != nullptr && current->frame.get() != frame) ++r.label_frame_waits;
  }
  r.label_answers = static_cast<int>(latency_ms.size());
  if (!latency_ms.empty()) {
    double sum = 0;
    for (double v : latency_ms) sum += v;
    r.label_mean_ms = sum / static_cast<double>(latency_ms.size());
    std::vector<double> sorted = latency_ms;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t p95 = std::min(sorted.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(sorted.size())));
    r.label_p95_ms = sorted[p95];
    r.label_max_ms = sorted.back();
  }
  memory.done();
}

}  // namespace

void PerfOptions::resolve() {
  auto pick = [this](int& value, int full, int quick_value) {
    if (value == 0) value = quick ? quick_value : full;
  };
  pick(frames, 240, 24);
  pick(train_frames, 300, 40);
  pick(model_rounds, 100, 20);
  pick(empty_frames, 150, 16);
  pick(answers, 300, 30);
  pick(positives, 5628, 200);
  pick(negatives, 22454, 800);
  pick(native_rounds, 20, 5);
  if (opencv_rounds.empty()) opencv_rounds = quick ? "1,2" : "1,3";
  if (threads < 1) throw Error("--threads must be 1 or more");
  for (int v : {frames, train_frames, model_rounds, empty_frames, answers, positives, negatives, native_rounds}) {
    if (v < 1) throw Error("sizes (--frames, --train-frames, ...) must be 1 or more");
  }
  if (frames > 999999 || train_frames > 999999 || empty_frames > 999999) throw Error("at most 999999 frames");
  int a = 0, b = 0;
  if (std::sscanf(opencv_rounds.c_str(), "%d,%d", &a, &b) != 2 || !((a == 0 && b == 0) || (a > 0 && b > a))) {
    throw cli::UsageError("--opencv-rounds must be A,B with 0 < A < B (or 0,0 to skip OpenCV), not '" + opencv_rounds + "'");
  }
}

PerfResults run_perf_report(const PerfOptions& options) {
  PerfOptions o = options;
  o.resolve();
  PerfResults r;
  machine(r, o);
  Workspace work;
  if (o.work_dir.empty()) {
    std::string pattern = (fs::temp_directory_path() / "rdsf-perf-report-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw Error("cannot create a temporary folder under " + fs::temp_directory_path().string());
    work.root = pattern;
    work.remove = true;
  } else {
    work.root = o.work_dir;
    if (fs::exists(work.root) && !fs::is_empty(work.root)) {
      throw Error(o.work_dir + ": --work folder is not empty (its frames and sample sets would be mixed in)");
    }
    fs::create_directories(work.root);
  }
  say(std::string(o.quick ? "quick" : "full") + " run; scratch folder " + work.root.string() + "; load average " +
      r.load_start);

  std::vector<DepthFrame> frames = render_people(r, o, work.root / "people");
  const BoostedModel model = train_pipeline_model(r, o);
  const std::vector<std::vector<int>> reference = whole_system_one_thread(r, o, frames, model);
  whole_system_parallel(r, o, frames, model, reference);
  shipped_default_model(r, o, frames);
  live_mode(r, o, frames, model);
  std::vector<DepthFrame>().swap(frames);  // the frames in memory are not part of the later phases
  png_reading(r, o, work.root / "people", model, reference);
  training_per_round(r, o);
  mining(r, o, work.root);
  labelling(r, o, work.root, model);
  r.load_end = clock::load_average_now();
  r.reference_end_ms = clock::reference_loop_ms();
  r.reference_end_gbps = read_bandwidth_gbps(256, 1, 3);
  return r;
}

}  // namespace rdsf::perf
