#pragma once
// rdsf-detect's work: run the whole system over a frame source, write the CSV, save or show pictures, and
// with --truth evaluate one or more models over a threshold sweep.
#include <string>
#include <vector>

#include "rdsf/frame/camera_model.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"

namespace rdsf {

struct DetectOptions {
  std::string source;
  std::vector<std::string> models;  ///< files or names; the first drives CSV, pictures and tracking output
  std::string models_dir = "models";
  /// Without --model: report candidates only instead of running the default model (models/people).
  bool candidates_only = false;
  std::string out_csv;     ///< empty: no CSV
  std::string save_dir;    ///< empty: no pictures
  bool show = false;
  bool force = false;      ///< replace an existing CSV or report
  std::string truth_csv;   ///< boxes.csv: evaluate
  std::string report_dir;  ///< where the evaluation goes
  std::vector<double> thresholds;  ///< the sweep
  double min_visible = 0.5;        ///< people less visible than this are "don't care" in the evaluation
  int clip_frames = 100;           ///< numbered frames per clip of the intervals over clips (clip_bootstrap.hpp)
  CameraModel camera;
  FrameSourceOptions frames;  ///< the camera model above, whether it was given, a bag's topics
  PipelineParams pipeline;
  /// --background: the folder of a background model of the room (empty: off).
  std::string background;
  /// --feature-spec was given: the first model must have that spec (else the detector takes the model's).
  bool feature_spec_given = false;
  /// Threads analysing frames (0: one per core); the results do not depend on it.
  int threads = 0;
  /// Stop after this many frames, reading none beyond (0: every frame; a device never ends by itself).
  std::int64_t max_frames = 0;
  /// Live mode: frames pushed as they arrive to LivePipeline (at most one waiting per worker, the oldest
  /// dropped); prints drops and latency percentiles. Sources that are not devices are paced at `fps`.
  bool live = false;
  double fps = 30;
};

/// Checks the options together (cli::UsageError naming the option, exit 2) and, when no model is named, adds
/// the default model (except for --truth without a model: candidate coverage only). Call once, before run_detect.
void check_options(DetectOptions& options);

/// Returns the process exit code.
int run_detect(const DetectOptions& options);

}  // namespace rdsf
