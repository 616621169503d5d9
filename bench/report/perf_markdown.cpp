// The Markdown report and the stdout summary of rdsf-perf-report.
#include <cstdio>
#include <sstream>

#include "perf_run.hpp"

namespace rdsf::perf {
namespace {

// The thesis's figures (timing chapter) and the project's targets (issues 7 and 9).
constexpr double kThesisSegmentationBestMs = 200, kThesisSegmentationWorstMs = 320;
constexpr double kThesisCandidateMs = 10;           // candidate initialisation, per candidate
constexpr double kThesisFeaturesClassifierMs = 16;  // RDSF and classifier, per candidate
constexpr double kThesisFps = 2.2;
constexpr double kTargetSegmentationRatio = 30, kTargetFps = 30, kTargetTrainingRatio = 100, kTargetLabelMs = 30;
constexpr double kEqualAucTolerance = 0.005;
constexpr double kTargetLiveP99Ms = 10;  // live mode at 30 and 90 fps: no drop, p99 latency under 10 ms (issue 15)
constexpr double kTargetMiningFps = 300;  // mining with colour on 2 cores (issue 17)
// Issue 34's budget on one core: segmentation and candidates per frame, RDSF and classifier per candidate.
constexpr double kBudgetFrontMs = 0.8, kBudgetPerCandidateMs = 0.010;

bool live_met(const PerfResults& r) {
  if (r.live.empty()) return false;
  for (const PerfResults::LiveRun& l : r.live) {
    if (l.stats.dropped != 0 || l.stats.p99_ms >= kTargetLiveP99Ms) return false;
  }
  return true;
}

std::string num(double v, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

/// Milliseconds with sensible precision (0.0123 ms, 1.23 ms, 123 ms).
std::string ms(double v) {
  if (v < 0.1) return num(v, 4) + " ms";
  if (v < 10) return num(v, 2) + " ms";
  return num(v, 0) + " ms";
}

std::string times(double ratio) { return num(ratio, ratio < 10 ? 1 : 0) + "x"; }
std::string yes_no(bool met) { return met ? "**yes**" : "**no**"; }

// " (median of N passes; slowest-fastest fps)" for a whole-system line, nothing for one pass.
std::string pass_range(const PerfResults& r, double fastest_s, double slowest_s) {
  if (r.whole_passes <= 1 || fastest_s <= 0 || slowest_s <= 0) return "";
  return " (median of " + std::to_string(r.whole_passes) + " passes; " + num(r.frames / slowest_s, 0) + "-" +
         num(r.frames / fastest_s, 0) + ")";
}

// "<before>median of N runs, slowest-fastest<after>" for a mining line, nothing for one run.
std::string mining_range(const PerfResults& r, double fastest_s, double slowest_s, const std::string& before,
                         const std::string& after) {
  if (r.mining_passes <= 1 || fastest_s <= 0 || slowest_s <= 0) return "";
  const double frames = static_cast<double>(r.mined_frames);
  return before + "median of " + std::to_string(r.mining_passes) + " runs, " + num(frames / slowest_s, 1) + "-" +
         num(frames / fastest_s, 1) + after;
}

struct Derived {
  double frames, candidates_per_frame, seg_ms, cand_per_candidate_ms, features_per_candidate_ms,
      classifier_per_candidate_ms, feat_cls_per_candidate_ms, tracking_ms, one_thread_ms, one_thread_fps,
      parallel_fps, files_fps, png_fps, mining_fps, training_ratio, training_cpu_ratio;
  bool equal_auc;
};

Derived derive(const PerfResults& r) {
  Derived d{};
  d.frames = r.frames > 0 ? r.frames : 1;
  const double cands = r.candidates > 0 ? static_cast<double>(r.candidates) : 1.0;
  d.candidates_per_frame = static_cast<double>(r.candidates) / d.frames;
  d.seg_ms = r.stage_ms.segmentation_ms / d.frames;
  d.cand_per_candidate_ms = r.stage_ms.candidates_ms / cands;
  d.features_per_candidate_ms = r.stage_ms.features_ms / cands;
  d.classifier_per_candidate_ms = r.stage_ms.classifier_ms / cands;
  d.feat_cls_per_candidate_ms = d.features_per_candidate_ms + d.classifier_per_candidate_ms;
  d.tracking_ms = r.stage_ms.tracking_ms / d.frames;
  d.one_thread_ms = 1000.0 * r.pipeline_wall_s / d.frames;
  d.one_thread_fps = r.pipeline_wall_s > 0 ? d.frames / r.pipeline_wall_s : 0;
  d.parallel_fps = r.parallel_wall_s > 0 ? d.frames / r.parallel_wall_s : 0;
  d.files_fps = r.files_parallel_wall_s > 0 ? d.frames / r.files_parallel_wall_s : 0;
  d.png_fps = r.png_read_ms_per_frame > 0 ? 1000.0 / r.png_read_ms_per_frame : 0;
  d.mining_fps = r.mining_wall_s > 0 ? static_cast<double>(r.mined_frames) / r.mining_wall_s : 0;
  d.training_ratio = r.native_s_per_round > 0 ? r.opencv_s_per_round / r.native_s_per_round : 0;
  d.training_cpu_ratio = r.native_cpu_s_per_round > 0 ? r.opencv_cpu_s_per_round / r.native_cpu_s_per_round : 0;
  d.equal_auc = r.native_auc_at_b >= r.opencv_auc_at_b - kEqualAucTolerance;
  return d;
}

// The title, the machine, its load and speed, the data and the model.
void write_header(const PerfResults& r, const Derived& d, std::ostringstream& m) {
  m << "# Performance report\n\n"
    << "Produced by `scripts/perf-report.sh` (program `rdsf-perf-report`, " << r.mode << " run) on " << r.date_utc
    << ", all phases in one process on the same data.\n\n"
    << "**Machine:** " << r.cpu_model << ", " << r.cores << " cores, " << num(r.memory_gib, 1)
    << " GiB memory. **Load average** (1 / 5 / 15 min) at the start: " << r.load_start << "; at the end: "
    << r.load_end << " (the cores are shared with other work, so figures can be lower than on an idle machine). "
    << "**Machine speed:** a fixed single-thread integer loop (2 * 10^7 dependent steps) took "
    << num(r.reference_start_ms, 1) << " ms of processor time at the start and " << num(r.reference_end_ms, 1)
    << " ms at the end; streaming reads of 256 MiB on one thread ran at " << num(r.reference_start_gbps, 1)
    << " and " << num(r.reference_end_gbps, 1)
    << " GB/s. The loop follows the clock rate, the reads what neighbours on the host take of the memory "
       "system; the load average shows neither, so compare two runs' figures only when these agree.\n\n"
    << "**Data:** " << r.frames << " synthetic frames of " << r.width_px << "x" << r.height_px << " with "
    << r.people_min << ".." << r.people_max << " people and registered colour (rdsf::synth::SynthSequence, "
    << num(r.render_ms_per_frame, 1) << " ms per frame to render, not counted below), " << num(d.candidates_per_frame, 1)
    << " candidates per frame. Model: native Real AdaBoost, " << r.model_rounds << " rounds, trained in this run on "
    << r.train_positives << " people and " << r.train_negatives << " other candidates of " << r.train_frames
    << " other synthetic frames (validation AUC " << num(r.model_validation_auc, 4) << "); " << r.detections
    << " detections, " << r.people_tracked << " people tracked.\n\n";
}

// Whole system per frame and per candidate, against the thesis.
void write_whole_system(const PerfResults& r, const Derived& d, std::ostringstream& m) {
  m << "## Whole system per frame and per candidate\n\n"
    << "| Stage | This run | Thesis | Ratio |\n|---|---|---|---|\n"
    << "| Segmentation per frame | " << ms(d.seg_ms) << " | " << num(kThesisSegmentationBestMs, 0) << "-"
    << num(kThesisSegmentationWorstMs, 0) << " ms | " << times(kThesisSegmentationBestMs / d.seg_ms)
    << " faster than the best |\n"
    << "| Candidate initialisation and filtering per candidate | " << ms(d.cand_per_candidate_ms) << " | "
    << num(kThesisCandidateMs, 0) << " ms | " << times(kThesisCandidateMs / d.cand_per_candidate_ms) << " faster |\n"
    << "| RDSF per candidate | " << ms(d.features_per_candidate_ms) << " | (in the 16 ms below) | - |\n"
    << "| Classifier per candidate | " << ms(d.classifier_per_candidate_ms) << " | (in the 16 ms below) | - |\n"
    << "| RDSF and classifier per candidate | " << ms(d.feat_cls_per_candidate_ms) << " | "
    << num(kThesisFeaturesClassifierMs, 0) << " ms | " << times(kThesisFeaturesClassifierMs / d.feat_cls_per_candidate_ms)
    << " faster |\n"
    << "| Tracking per frame | " << ms(d.tracking_ms) << " | - | - |\n"
    << "| Whole system, 1 thread | " << ms(d.one_thread_ms) << " per frame = " << num(d.one_thread_fps, 1)
    << " fps" << pass_range(r, r.pipeline_wall_min_s, r.pipeline_wall_max_s) << " | " << num(kThesisFps, 1) << " fps | "
    << times(d.one_thread_fps / kThesisFps) << " |\n"
    << "| Whole system, " << r.threads << " threads (frames in memory) | " << num(d.parallel_fps, 1) << " fps"
    << pass_range(r, r.parallel_wall_min_s, r.parallel_wall_max_s) << " | " << num(kThesisFps, 1) << " fps | "
    << times(d.parallel_fps / kThesisFps) << " |\n"
    << "| PNG reading per frame (depth and colour), 1 thread | " << ms(r.png_read_ms_per_frame) << " = "
    << num(d.png_fps, 1) << " fps | - | - |\n"
    << "| Whole system from PNG files, " << r.threads << " threads | " << num(d.files_fps, 1) << " fps | "
    << num(kThesisFps, 1) << " fps | " << times(d.files_fps / kThesisFps) << " |\n\n"
    << "Stage times are PeoplePipeline's own (summed over all frames, divided by frames or by the "
    << r.candidates << " candidates; RDSF is only the features the model reads, see docs/features.md, with "
    << "scores identical to the full vector's, of the crop and of its mirror in one pass (mirror averaging, the default: "
    << "`ModelScorer::compute_with_mirror`), so the classifier is the scores alone); the 1-thread line is the wall time of `PeoplePipeline::process`; both whole-system lines "
    << "give the median of their passes over the frames (a fresh pipeline each), the stage times are the median 1-thread pass's. The "
    << r.threads << "-thread lines analyse frames (segmentation, candidates, RDSF, scores, colour histograms) on "
    << r.threads << " threads (the calling thread one of them) and track in frame order on the calling thread; their person ids are "
    << (r.parallel_identical ? "identical to" : "**different from**") << " the 1-thread run's. "
    << "Showing (drawing) is not included. Both multi-thread lines run the library's parallel pipeline "
    << "(`run_in_frame_order`, include/rdsf/pipeline/parallel_pipeline.hpp), the code `rdsf-detect --threads` runs.\n\n";
}

// The shipped default model as a detector runs it, beside this run's own model (the rows above).
void write_shipped_model(const PerfResults& r, const Derived& d, std::ostringstream& m) {
  const PerfResults::ShippedRun& s = r.shipped;
  if (s.model.empty()) return;
  const double cands = s.candidates > 0 ? static_cast<double>(s.candidates) : 1.0;
  const double front_ms = (s.stage_ms.segmentation_ms + s.stage_ms.candidates_ms) / d.frames;
  const double own_front_ms = (r.stage_ms.segmentation_ms + r.stage_ms.candidates_ms) / d.frames;
  const double per_candidate_ms = (s.stage_ms.features_ms + s.stage_ms.classifier_ms) / cands;
  const double one_fps = s.wall_s > 0 ? d.frames / s.wall_s : 0, par_fps = s.parallel_wall_s > 0 ? d.frames / s.parallel_wall_s : 0;
  const std::string options = s.options.empty() ? "no detection option" : s.options;
  m << "## The shipped default model, as a detector runs it\n\n"
    << "| Measure | " << s.model << " (" << options << ", " << s.rounds << " weak classifiers) | This run's model ("
    << "the detector's defaults, " << r.model_rounds << " rounds) | Budget |\n|---|---|---|---|\n"
    << "| Segmentation and candidates per frame | " << ms(front_ms) << " | " << ms(own_front_ms)
    << " | " << ms(kBudgetFrontMs) << " |\n"
    << "| Candidates per frame | " << num(static_cast<double>(s.candidates) / d.frames, 1) << " | "
    << num(d.candidates_per_frame, 1) << " | - |\n"
    << "| RDSF and classifier per candidate | " << ms(per_candidate_ms) << " | " << ms(d.feat_cls_per_candidate_ms)
    << " | " << ms(kBudgetPerCandidateMs) << " |\n"
    << "| Whole system, 1 thread | " << num(one_fps, 1) << " fps" << pass_range(r, s.wall_min_s, s.wall_max_s) << " | "
    << num(d.one_thread_fps, 1) << " fps | - |\n"
    << "| Whole system, " << r.threads << " threads (frames in memory) | " << num(par_fps, 1) << " fps"
    << pass_range(r, s.parallel_wall_min_s, s.parallel_wall_max_s) << " | " << num(d.parallel_fps, 1) << " fps | "
    << num(kTargetFps, 0) << " fps |\n\n"
    << "`rdsf-detect` without `--model` runs the shipped default model: the newest `people` of models/, with the "
    << "detection options it states taken (include/rdsf/pipeline/stated_options.hpp) and read at its operating point; "
    << "the same frames, passes and threads as the rows above, which run a model trained in this run that states "
    << "nothing. Its " << s.detections << " detections; its person ids on " << r.threads << " threads are "
    << (s.parallel_identical ? "identical to" : "**different from**") << " its 1-thread run's. The budgets are "
    << "issue 34's (segmentation and candidates, and RDSF and classifier per candidate, on one core).\n\n";
}

// Live mode: drops and latency at each camera rate.
void write_live_mode(const PerfResults& r, std::ostringstream& m) {
  m << "## Live mode\n\n| Camera rate | Frames | Dropped | Latency p50 | p95 | p99 | max |\n|---|---|---|---|---|---|---|\n";
  for (const PerfResults::LiveRun& l : r.live) {
    m << "| " << num(l.fps, 0) << " fps | " << l.stats.arrived << " | " << l.stats.dropped << " | "
      << ms(l.stats.p50_ms) << " | " << ms(l.stats.p95_ms) << " | " << ms(l.stats.p99_ms) << " | "
      << ms(l.stats.max_ms) << " |\n";
  }
  m << "\nThe frames in memory pushed at the camera's rate to `LivePipeline` (include/rdsf/pipeline/live_pipeline.hpp, "
    << "what `rdsf-detect --live` runs) with " << r.threads << " workers: at most one frame waits per worker, a "
    << "newer frame replaces the oldest waiting one (dropped); latency is from the push to the detections out "
    << "(after tracking).\n\n";
}

// Training per round: native against OpenCV.
void write_training(const PerfResults& r, const Derived& d, std::ostringstream& m) {
  const bool huge_tree = r.train_rows_positive == 5628 && r.train_rows_negative == 22454;
  m << "## Training per round\n\n"
    << r.train_rows_positive << " + " << r.train_rows_negative << " training rows"
    << (huge_tree ? " (the thesis's hugeTree size)" : " (smaller than the thesis's hugeTree: 5628 + 22454)") << " x "
    << r.dimension
    << " RDSF features (generated crops as in bench/bench_train.cpp, " << num(r.rows_generate_s, 1)
    << " s to make), " << r.validation_rows << " validation rows.\n\n"
    << "| Trainer | Time per round | Processor time per round | Set-up | Validation AUC after " << r.opencv_b
    << " rounds |\n|---|---|---|---|---|\n"
    << "| Native Real AdaBoost (" << r.threads << " threads, " << r.native_rounds << " rounds timed) | "
    << num(r.native_s_per_round, 3) << " s | " << num(r.native_cpu_s_per_round, 3) << " s | "
    << num(r.native_binning_s, 1) << " s binning | " << num(r.native_auc_at_b, 4) << " |\n";
  if (r.opencv_ran) {
    m << "| OpenCV cv::ml::Boost REAL stumps | " << num(r.opencv_s_per_round, 2) << " s | "
      << num(r.opencv_cpu_s_per_round, 2) << " s | " << num(r.opencv_setup_s, 1) << " s | "
      << num(r.opencv_auc_at_b, 4) << " |\n"
      << "| Ratio (OpenCV / native) | " << times(d.training_ratio) << " | " << times(d.training_cpu_ratio)
      << " | - | "
      << (r.native_auc_at_b - r.opencv_auc_at_b >= 0 ? "+" : "") << num(r.native_auc_at_b - r.opencv_auc_at_b, 4)
      << " |\n\n"
      << "OpenCV trains all rounds in one call, so it was timed at " << r.opencv_a << " round(s) ("
      << num(r.opencv_a_s, 1) << " s) and " << r.opencv_b << " rounds (" << num(r.opencv_b_s, 1)
      << " s); its time per round is the difference divided by " << (r.opencv_b - r.opencv_a)
      << " (the fixed set-up cancels out) and extrapolates linearly: 100 rounds ~ "
      << num(r.opencv_setup_s + 100 * r.opencv_s_per_round, 0) << " s against the native "
      << num(r.native_binning_s + 100 * r.native_s_per_round, 0) << " s. Native AUC after all "
      << r.native_rounds << " rounds: " << num(r.native_auc_final, 4) << "; ";
    if (r.native_rounds_to_opencv_auc > 0) {
      m << "the native trainer reaches OpenCV's " << r.opencv_b << "-round AUC after " << r.native_rounds_to_opencv_auc
        << " round(s).\n\n";
    } else {
      m << "the native trainer did not reach OpenCV's " << r.opencv_b << "-round AUC in " << r.native_rounds
        << " rounds.\n\n";
    }
  } else {
    m << "| OpenCV cv::ml::Boost REAL stumps | not run (--opencv-rounds 0,0) | - | - | - |\n\n";
  }
}

// Mining and labelling against their targets.
void write_mining_and_labelling(const PerfResults& r, const Derived& d, std::ostringstream& m) {
  m << "## Mining and labelling\n\n| Measure | This run | Target |\n|---|---|---|\n"
    << "| Mining negatives, " << r.threads << " threads (PNG frames with colour) | "
    << num(d.mining_fps, 1) << " fps (" << r.mined_frames << " frames, " << r.mined_candidates << " candidates, "
    << r.mined_kept << " kept" << mining_range(r, r.mining_wall_min_s, r.mining_wall_max_s, "; ", "") << ") | "
    << num(kTargetMiningFps, 0) << " fps |\n"
    << "| ... the same into a set in memory (/dev/shm: no disk) | "
    << (r.mining_memory_wall_s > 0
            ? num(static_cast<double>(r.mined_frames) / r.mining_memory_wall_s, 1) + " fps" +
                  mining_range(r, r.mining_memory_wall_min_s, r.mining_memory_wall_max_s, " (", ")")
            : std::string("not measured (no /dev/shm)"))
    << " | " << num(kTargetMiningFps, 0) << " fps |\n"
    << "| Labelling: answer to next candidate, mean | " << ms(r.label_mean_ms) << " | " << num(kTargetLabelMs, 0)
    << " ms |\n"
    << "| Labelling: answer to next candidate, 95 % | " << ms(r.label_p95_ms) << " | " << num(kTargetLabelMs, 0)
    << " ms |\n"
    << "| Labelling: answer to next candidate, max | " << ms(r.label_max_ms) << " | " << num(kTargetLabelMs, 0)
    << " ms |\n\n"
    << "Labelling: a headless LabelingSession on the " << r.frames << " PNG frames with the model, "
    << r.label_answers << " answers given instantly (y when H(x) >= 0, else n; each y appends a sample with its "
    << "crops and syncs it to disk); " << r.label_frame_waits
    << " of them moved on to the next frame, which the session reads and analyses in the background while a "
       "person would decide, so an instant answer is the worst case.\n\n";
}

// Memory peaks per phase.
void write_memory_peaks(const PerfResults& r, std::ostringstream& m) {
  m << "## Memory peaks\n\n| Phase | Resident at start | Peak (VmHWM) |\n|---|---|---|\n";
  for (const PhaseMemory& p : r.memory) {
    m << "| " << p.phase << " | " << num(p.start_mib, 0) << " MiB | " << num(p.peak_mib, 0) << " MiB"
      << (p.reset ? "" : " (peak not reset)") << " |\n";
  }
  m << "\nThe peak is reset at the start of each phase (`5` written to /proc/self/clear_refs); what is resident at "
       "the start (the program, the model, the "
    << num(r.frames_mib, 0) << " MiB of frames kept in memory for the whole-system phases) is part of the peak.\n\n";
}

// The targets, each measured and met or not.
void write_targets(const PerfResults& r, const Derived& d, std::ostringstream& m) {
  m << "## Targets\n\n| Target | Measured | Met |\n|---|---|---|\n"
    << "| Segmentation >= " << num(kTargetSegmentationRatio, 0) << "x faster than the thesis's best ("
    << num(kThesisSegmentationBestMs, 0) << " ms) | " << times(kThesisSegmentationBestMs / d.seg_ms) << " ("
    << ms(d.seg_ms) << ") | " << yes_no(kThesisSegmentationBestMs / d.seg_ms >= kTargetSegmentationRatio) << " |\n"
    << "| Whole system >= " << num(kTargetFps, 0) << " fps on 2 cores | " << num(d.parallel_fps, 1) << " fps on "
    << r.threads << " threads (" << num(d.one_thread_fps, 1) << " on 1, " << num(d.files_fps, 1)
    << " from PNG files) | " << yes_no(d.parallel_fps >= kTargetFps && r.threads <= 2) << " |\n";
  if (r.opencv_ran) {
    m << "| Training >= " << num(kTargetTrainingRatio, 0) << "x faster per round than OpenCV at equal AUC | "
      << times(d.training_ratio) << " wall time (" << times(d.training_cpu_ratio) << " processor time), AUC "
      << num(r.native_auc_at_b, 4) << " vs " << num(r.opencv_auc_at_b, 4)
      << " | " << yes_no(d.training_ratio >= kTargetTrainingRatio && d.equal_auc) << " |\n";
  } else {
    m << "| Training >= " << num(kTargetTrainingRatio, 0) << "x faster per round than OpenCV at equal AUC | "
      << "not measured | - |\n";
  }
  m << "| Live mode at 30 and 90 fps on " << r.threads << " workers: no drop, p99 < " << num(kTargetLiveP99Ms, 0)
    << " ms | ";
  for (std::size_t i = 0; i < r.live.size(); ++i) {
    m << (i ? "; " : "") << num(r.live[i].fps, 0) << " fps: " << r.live[i].stats.dropped << " dropped, p99 "
      << ms(r.live[i].stats.p99_ms);
  }
  m << " | " << yes_no(live_met(r) && r.threads <= 2) << " |\n";
  m << "| Labelling: next candidate within " << num(kTargetLabelMs, 0) << " ms | 95 % " << ms(r.label_p95_ms)
    << ", max " << ms(r.label_max_ms) << " | " << yes_no(r.label_p95_ms <= kTargetLabelMs) << " |\n\n"
    << "The training target is judged on wall time (\"on 2 cores\": the native trainer uses " << r.threads
    << " threads, OpenCV one); the processor-time ratio adds up every thread, i.e. it is the speed-up per core. "
    << "Equal AUC means the native validation AUC after " << r.opencv_b << " rounds is at least OpenCV's minus "
    << kEqualAucTolerance << ". The labelling target is judged on the 95th percentile.\n";
}

}  // namespace

std::string perf_markdown(const PerfResults& r) {
  const Derived d = derive(r);
  std::ostringstream m;
  write_header(r, d, m);
  write_whole_system(r, d, m);
  write_shipped_model(r, d, m);
  write_live_mode(r, m);
  write_training(r, d, m);
  write_mining_and_labelling(r, d, m);
  write_memory_peaks(r, m);
  write_targets(r, d, m);
  return m.str();
}

std::string perf_summary(const PerfResults& r) {
  const Derived d = derive(r);
  std::ostringstream s;
  s << "segmentation " << ms(d.seg_ms) << " per frame: " << times(kThesisSegmentationBestMs / d.seg_ms)
    << " faster than the thesis's 200 ms (target 30x)\n"
    << "candidates " << ms(d.cand_per_candidate_ms) << " per candidate: "
    << times(kThesisCandidateMs / d.cand_per_candidate_ms) << " faster than 10 ms\n"
    << "RDSF + classifier " << ms(d.feat_cls_per_candidate_ms) << " per candidate: "
    << times(kThesisFeaturesClassifierMs / d.feat_cls_per_candidate_ms) << " faster than 16 ms\n"
    << "whole system " << num(d.one_thread_fps, 1) << " fps on 1 thread, " << num(d.parallel_fps, 1) << " fps on "
    << r.threads << " threads (" << times(d.parallel_fps / kThesisFps) << " the thesis's 2.2; target 30), "
    << num(d.files_fps, 1) << " fps from PNG files\n";
  if (!r.shipped.model.empty() && r.shipped.wall_s > 0 && r.shipped.parallel_wall_s > 0) {
    s << "the shipped default model " << r.shipped.model << (r.shipped.options.empty() ? "" : " (" + r.shipped.options + ")")
      << ": " << num(d.frames / r.shipped.wall_s, 1) << " fps on 1 thread, " << num(d.frames / r.shipped.parallel_wall_s, 1)
      << " fps on " << r.threads << " threads\n";
  }
  for (const PerfResults::LiveRun& l : r.live) {
    s << "live mode at " << num(l.fps, 0) << " fps: " << l.stats.dropped << " of " << l.stats.arrived
      << " frames dropped, latency p50 " << ms(l.stats.p50_ms) << ", p95 " << ms(l.stats.p95_ms) << ", p99 "
      << ms(l.stats.p99_ms) << " (target: no drop, p99 < 10 ms)\n";
  }
  if (r.opencv_ran) {
    s << "training per round: native " << num(r.native_s_per_round, 3) << " s, OpenCV "
      << num(r.opencv_s_per_round, 2) << " s: " << times(d.training_ratio) << " (target 100x; processor time "
      << times(d.training_cpu_ratio) << "); AUC after "
      << r.opencv_b << " rounds " << num(r.native_auc_at_b, 4) << " vs " << num(r.opencv_auc_at_b, 4) << "\n";
  }
  s << "mining " << num(d.mining_fps, 1) << " fps; labelling next candidate mean " << ms(r.label_mean_ms) << ", 95 % "
    << ms(r.label_p95_ms) << ", max " << ms(r.label_max_ms) << " (target 30 ms)\n";
  return s.str();
}

}  // namespace rdsf::perf
