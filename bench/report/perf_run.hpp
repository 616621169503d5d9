#pragma once
// The performance report of rdsf-perf-report: every measurement in one process, on the same data, with
// the figures of the thesis and the project's targets beside them.
#include <string>
#include <vector>

#include "rdsf/pipeline/live_pipeline.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"

namespace rdsf::perf {

/// Sizes of the run; 0 (or empty) means the mode's default (full, or --quick for a smoke run).
struct PerfOptions {
  std::string out = "perf-report.md";  ///< Markdown report
  bool force = false;                  ///< replace an existing report
  bool quick = false;                  ///< small sizes: a smoke run in well under a minute
  std::string work_dir;                ///< scratch folder for PNG frames and sample sets; empty: a temporary one, removed
  int threads = 2;                     ///< threads of the parallel measurements (the target is "on 2 cores")
  int frames = 0;                      ///< frames with people for the whole system (full 240, quick 24)
  int train_frames = 0;                ///< frames whose candidates train the pipeline's model (full 300, quick 40)
  int model_rounds = 0;                ///< rounds of the pipeline's model (full 100, quick 20)
  int empty_frames = 0;                ///< people-free frames for mining (full 150, quick 16)
  int answers = 0;                     ///< answers given in the labelling session (full 300, quick 30)
  int positives = 0, negatives = 0;    ///< training comparison rows (full 5628 + 22454 = hugeTree, quick 200 + 800)
  int native_rounds = 0;               ///< native rounds timed (full 20, quick 5)
  std::string opencv_rounds;           ///< "A,B": OpenCV timed at A and B rounds (full "1,3", quick "1,2"; "0,0" skips)

  /// Fills every 0 / empty size with the mode's default; throws Error on impossible values.
  void resolve();
};

struct PhaseMemory {
  std::string phase;
  double start_mib = 0;  ///< resident at the start of the phase
  double peak_mib = 0;   ///< VmHWM over the phase
  bool reset = false;    ///< peak reset at the start (else the process's peak so far)
};

struct PerfResults {
  // Machine and run
  std::string date_utc, mode, cpu_model, load_start, load_end;
  /// The machine's speed at the start and at the end of the run: clock::reference_loop_ms() (the clock
  /// rate) and streaming reads of 256 MiB on one thread (GB/s; what neighbours on the host take shows here).
  double reference_start_ms = 0, reference_end_ms = 0;
  double reference_start_gbps = 0, reference_end_gbps = 0;
  int cores = 0;
  double memory_gib = 0;
  // Data
  int frames = 0, people_min = 1, people_max = 4, width_px = 640, height_px = 480;
  double render_ms_per_frame = 0, frames_mib = 0;
  int train_frames = 0, train_positives = 0, train_negatives = 0, model_rounds = 0;
  double model_validation_auc = 0, model_train_s = 0;
  // Whole system, one thread (PeoplePipeline)
  // Each whole-system line runs `whole_passes` times over the frames (a fresh pipeline each time): the
  // median pass is reported, with the fastest and slowest beside it.
  int whole_passes = 1;
  StageTimes stage_ms;          ///< sums over all frames (the median pass)
  double pipeline_wall_s = 0;      ///< wall time of all process() calls (the median pass)
  double pipeline_wall_min_s = 0, pipeline_wall_max_s = 0;
  long long candidates = 0, detections = 0;
  int people_tracked = 0;
  // Whole system, frames analysed on `threads` threads, tracking in frame order
  int threads = 2;
  double parallel_wall_s = 0, parallel_wall_min_s = 0, parallel_wall_max_s = 0;  ///< median, fastest, slowest pass
  bool parallel_identical = false;  ///< same person ids as the one-thread run
  // The shipped default model (models/people, the newest version) as a detector runs it: its stated detection
  // options taken, read at its operating point; the same frames, passes and threads as the lines above.
  struct ShippedRun {
    std::string model;    ///< "people v4"
    std::string options;  ///< the options it states that differ from the detector's defaults ("--local-front 70")
    int rounds = 0;       ///< its weak classifiers
    long long candidates = 0, detections = 0;
    StageTimes stage_ms;  ///< sums over all frames (the median 1-thread pass)
    double wall_s = 0, wall_min_s = 0, wall_max_s = 0;                    ///< 1 thread: median, fastest, slowest
    double parallel_wall_s = 0, parallel_wall_min_s = 0, parallel_wall_max_s = 0;  ///< `threads` threads
    bool parallel_identical = false;  ///< the same person ids as its 1-thread run
  } shipped;
  // Live mode (LivePipeline, `threads` workers): frames in memory pushed at a camera's rate
  struct LiveRun {
    double fps = 0;
    LiveStats stats;
  };
  std::vector<LiveRun> live;
  // PNG reading
  double png_read_ms_per_frame = 0;   ///< depth + colour, one thread, through open_frame_source
  double files_parallel_wall_s = 0;   ///< whole system from the PNG files on `threads` threads
  // Training per round at hugeTree size
  int train_rows_positive = 0, train_rows_negative = 0, validation_rows = 0, dimension = 0;
  double rows_generate_s = 0, native_binning_s = 0, native_s_per_round = 0;
  int native_rounds = 0;
  bool opencv_ran = false;
  int opencv_a = 0, opencv_b = 0;
  double opencv_a_s = 0, opencv_b_s = 0, opencv_s_per_round = 0, opencv_setup_s = 0;
  /// Processor time (all threads of the process) per round: the cost without the wait for shared cores.
  double native_cpu_s_per_round = 0, opencv_cpu_s_per_round = 0;
  double native_auc_at_b = 0, opencv_auc_at_b = 0, native_auc_final = 0;
  int native_rounds_to_opencv_auc = -1;  ///< first native round whose AUC >= OpenCV's after B rounds (-1: none)
  // Mining
  long long mined_frames = 0, mined_candidates = 0, mined_kept = 0;
  /// Mining runs `mining_passes` times each way, alternated (disk, memory, disk, ...), each into a new set:
  /// the median pass is reported with the fastest and slowest (one 0.5 s run moves by 10-20 % here).
  int mining_passes = 1;
  double mining_wall_s = 0;  ///< into a set in the scratch folder (the disk a lab's sets are on)
  double mining_wall_min_s = 0, mining_wall_max_s = 0;
  /// The same frames into a set in memory (/dev/shm, when it is a folder): the processor's share without
  /// the disk's file creation and flushes (0: not measured).
  double mining_memory_wall_s = 0;
  double mining_memory_wall_min_s = 0, mining_memory_wall_max_s = 0;
  // Labelling
  int label_answers = 0, label_frame_waits = 0;
  double label_mean_ms = 0, label_p95_ms = 0, label_max_ms = 0;
  // Memory
  std::vector<PhaseMemory> memory;
};

/// Runs every phase (progress on stderr) and returns the figures.
PerfResults run_perf_report(const PerfOptions& options);

/// The Markdown report.
std::string perf_markdown(const PerfResults& r);
/// The short summary printed on stdout: ratios against the thesis and the targets.
std::string perf_summary(const PerfResults& r);

}  // namespace rdsf::perf
