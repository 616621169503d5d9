#pragma once
// Mining negatives: runs the frame analyser on people-free frames and appends every candidate to a sample
// set as a negative (label 0, origin "miner"), or in hard-negative mode only those a model scores at or
// above a threshold (its false positives, as in the bootstrapping of opencv_traincascade).
//
// Frames are analysed on worker threads and written by the calling thread in frame order, so the result
// does not depend on the number of threads. Exact duplicates (same label and place, or same depth crop)
// are skipped, which makes a rerun after a kill continue where it stopped without duplicating samples.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/frame/camera_model.hpp"

namespace rdsf {

struct MineParams {
  std::vector<std::string> sources;  ///< frame source specs (open_frame_source), mined one after another
  int stride = 1;                    ///< use frames whose index (0-based, per source) is a multiple of stride
  int shard_index = 1;               ///< this job's slice i (1-based) of shard_count ...
  int shard_count = 1;               ///< ... takes the strided frames k = index / stride with k % n == i - 1
  std::int64_t max_frames = 0;       ///< stop after this many frames (0: no limit)
  std::int64_t max_negatives = 0;    ///< stop once the set holds this many label-0 samples (0: no limit)
  int threads = 0;                   ///< worker threads analysing frames (0: one per core)
  bool depth_only = false;           ///< do not read colour: crops without colour, faster on PNG folders
  /// Group commit: the samples of up to this many frames are flushed to disk together (one sync of the
  /// crops, one of samples.tsv), and on_frame reports those frames after that flush, so a frame reported is
  /// on disk. The writer also flushes before a batch would exceed SampleSetWriter::kMaxUnsyncedRows rows.
  /// A kill or power cut loses at most the unreported frames since the last flush; rerunning the same
  /// command mines them again (duplicates are skipped). 1 flushes after every frame (before issue 17).
  int sync_every_frames = 16;
  CameraModel camera;
  AnalyserParams analyser;
  /// Hard-negative mode when set: the score H(x) of one candidate's masked depth crop (called from the
  /// worker threads); candidates below min_score are dropped.
  std::function<double(const cv::Mat1w&)> scorer;
  double min_score = 0;
  std::string model;  ///< recorded with each sample in hard-negative mode ("tree2/v3")
  /// How the crops are encoded (kSampleCropPng; {1}: cv::imencode's bytes, as main mined at ae93907).
  PngEncodeOptions crop_png = kSampleCropPng;
};

struct MineStats {
  std::int64_t frames = 0;       ///< frames analysed
  std::optional<std::int64_t> total_frames;  ///< frames that will be analysed, when known
  std::int64_t candidates = 0;   ///< candidates found in them
  std::int64_t below_score = 0;  ///< hard-negative mode: candidates scored below min_score
  std::int64_t duplicates = 0;   ///< exact duplicates skipped (already in the set)
  std::int64_t kept = 0;         ///< appended to the set
  bool reached_max = false;      ///< stopped by max_negatives
};

/// True when frame `index` of a source belongs to the stride / shard selection of `params`.
bool frame_selected(std::int64_t index, const MineParams& params);

/// Validates params (stride >= 1, 1 <= shard_index <= shard_count, ...); throws Error.
void check_mine_params(const MineParams& params);

class FrameFeeder;

/// The miner, in two steps so that bad sources fail before the output set is created or touched.
class NegativeMiner {
 public:
  /// Checks the params and opens every source; throws Error naming a bad one.
  explicit NegativeMiner(MineParams params);
  ~NegativeMiner();
  NegativeMiner(const NegativeMiner&) = delete;
  NegativeMiner& operator=(const NegativeMiner&) = delete;

  /// Frames that will be analysed (stride, shard and max_frames applied), when the sources know.
  std::optional<std::int64_t> total_frames() const { return total_frames_; }

  /// Mines every source into `out` (once). `on_frame` is called on the calling thread once before the
  /// first frame (frames 0, total_frames known) and after each flush to disk (every sync_every_frames
  /// frames, at most; at once after a frame that left nothing to flush), with the stats of every frame
  /// flushed so far. On an error, what was written is flushed (best effort) before the error is rethrown.
  MineStats run(SampleSetWriter& out, const std::function<void(const MineStats&)>& on_frame = {});

 private:
  MineParams params_;
  std::vector<std::unique_ptr<FrameFeeder>> feeders_;
  std::optional<std::int64_t> total_frames_;
};

/// NegativeMiner(params).run(out, on_frame).
MineStats mine_negatives(const MineParams& params, SampleSetWriter& out,
                         const std::function<void(const MineStats&)>& on_frame = {});

}  // namespace rdsf
