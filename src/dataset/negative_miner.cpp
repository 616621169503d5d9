#include "rdsf/dataset/negative_miner.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <tuple>

#include "rdsf/core/error.hpp"
#include "rdsf/core/ordered_pool.hpp"
#include "rdsf/dataset/sample_source.hpp"
#include "rdsf/features/feature_spec_record.hpp"
#include "rdsf/dataset/sample_crop.hpp"
#include "rdsf/frame/depth_png.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/frame/png_folder_source.hpp"

namespace rdsf {

namespace {

struct MinedCandidate {
  SampleRecord record;
  EncodedCrop crop;
  bool below_score = false;
};

struct FrameResult {
  std::vector<MinedCandidate> items;
};

}  // namespace

/// Hands out the selected frames of one source in order (claim, one call at a time); image folders are
/// decoded by load() on the workers (in parallel), other sources are read by claim().
class FrameFeeder {
 public:
  FrameFeeder(const std::string& spec, const MineParams& params, std::int64_t limit)
      : params_(params), limit_(limit), source_(open_frame_source(spec, params.camera)) {
    if (const auto* folder = dynamic_cast<const PngFolderSource*>(source_.get())) {
      const std::vector<std::string>& paths = folder->depth_paths();
      for (std::size_t i = 0; i < paths.size(); ++i) {
        if (frame_selected(static_cast<std::int64_t>(i), params)) {
          selected_.emplace_back(static_cast<std::int64_t>(i), paths[i]);
        }
      }
      random_access_ = true;
    }
  }

  std::string description() const { return source_->description(); }
  void set_limit(std::int64_t limit) { limit_ = limit; }

  std::optional<std::int64_t> selected_count() const {
    if (random_access_) return std::min<std::int64_t>(static_cast<std::int64_t>(selected_.size()), limit_);
    const std::optional<std::int64_t> count = source_->frame_count();
    if (!count) return std::nullopt;
    std::int64_t selected = 0;
    for (std::int64_t i = 0; i < *count; ++i) selected += frame_selected(i, params_) ? 1 : 0;
    return std::min(selected, limit_);
  }

  /// A claimed frame: for image folders its index and path (decoded by load()), else the frame read.
  struct Job {
    std::int64_t index = 0;
    std::string path;
    DepthFrame frame;
    bool read = false;
  };

  /// Takes the next selected frame; false at the end or at the limit. One call at a time (the ordered
  /// pool's claim); image folders only take the path here, other sources read the frame.
  bool claim(Job& job) {
    if (random_access_) {
      if (issued_ >= limit_ || issued_ >= static_cast<std::int64_t>(selected_.size())) return false;
      std::tie(job.index, job.path) = selected_[static_cast<std::size_t>(issued_++)];
      return true;
    }
    while (issued_ < limit_) {
      if (!source_->next(job.frame)) return false;
      if (frame_selected(job.frame.index, params_)) {
        ++issued_;
        if (params_.depth_only) job.frame.bgr.release();
        job.read = true;
        return true;
      }
    }
    return false;
  }

  /// The frame of a claimed job, decoding an image folder's files here (on any worker, concurrently).
  const DepthFrame& load(Job& job) const {
    if (job.read) return job.frame;
    DepthFrame& frame = job.frame;
    if (params_.depth_only) {  // as PngFolderSource::next, without the colour image
      frame.depth_mm = read_depth_png(job.path);
      frame.bgr.release();
      frame.name = PngFolderSource::frame_name(job.path);
      const CameraModel& camera = params_.camera;
      frame.camera = frame.depth_mm.size() == cv::Size(camera.width_px, camera.height_px)
                         ? camera
                         : camera.scaled_to(frame.depth_mm.cols, frame.depth_mm.rows);
    } else {
      auto single = open_frame_source(job.path, params_.camera);
      if (!single->next(frame)) fail(job.path, "delivered no frame");
    }
    frame.index = job.index;
    frame.timestamp_us = job.index * kFrameIntervalUs;  // as PngFolderSource: image folders carry no clock
    job.read = true;
    return frame;
  }

 private:
  const MineParams& params_;
  std::int64_t limit_;
  std::unique_ptr<FrameSource> source_;
  bool random_access_ = false;
  std::vector<std::pair<std::int64_t, std::string>> selected_;
  std::int64_t issued_ = 0;
};

namespace {

FrameResult analyse_frame(const FrameAnalyser& analyser, const MineParams& params, const std::string& source,
                          const DepthFrame& frame) {
  const bool hard = static_cast<bool>(params.scorer);
  const FrameAnalysis analysis = analyser.analyse(frame, /*with_features=*/false);  // the scorer computes its own
  FrameResult result;
  result.items.resize(analysis.candidates.size());
  for (std::size_t i = 0; i < analysis.candidates.size(); ++i) {
    const Candidate& c = analysis.candidates[i];
    MinedCandidate& m = result.items[i];
    m.record.label = 0;
    m.record.origin = "miner";
    m.record.source = source;
    m.record.frame = frame.name;
    m.record.strict_box = c.strict_box;
    m.record.window = c.window;
    m.record.layer_depth_mm = c.layer_depth_mm;
    if (hard) {
      const double score = params.scorer(c.depth_crop);
      m.record.model = params.model;
      m.record.score = score;
      m.below_score = score < params.min_score;
    }
    if (!m.below_score) {
      m.crop = EncodedCrop::encode(c.depth_crop, c.colour_crop, params.crop_png);
      m.record.crop_hash = m.crop.hash;
    }
  }
  return result;
}

}  // namespace

bool frame_selected(std::int64_t index, const MineParams& params) {
  if (index % params.stride != 0) return false;
  return (index / params.stride) % params.shard_count == params.shard_index - 1;
}

void check_mine_params(const MineParams& p) {
  if (p.sources.empty()) throw Error("mining: no frame source given");
  if (p.stride < 1) throw Error("mining: stride " + std::to_string(p.stride) + " must be at least 1");
  if (p.shard_count < 1 || p.shard_index < 1 || p.shard_index > p.shard_count) {
    throw Error("mining: shard " + std::to_string(p.shard_index) + "/" + std::to_string(p.shard_count) +
                " must be i/n with 1 <= i <= n");
  }
  if (p.max_frames < 0 || p.max_negatives < 0) throw Error("mining: limits must not be negative");
  if (p.sync_every_frames < 1) {
    throw Error("mining: sync every " + std::to_string(p.sync_every_frames) + " frames: must be at least 1");
  }
}

NegativeMiner::NegativeMiner(MineParams params) : params_(std::move(params)) {
  check_mine_params(params_);
  // Open every source first: a wrong spec fails before anything is mined; the total is known for progress.
  const std::int64_t no_limit = std::numeric_limits<std::int64_t>::max();
  std::optional<std::int64_t> total = 0;
  for (const std::string& spec : params_.sources) {
    feeders_.push_back(std::make_unique<FrameFeeder>(spec, params_, no_limit));
    const std::optional<std::int64_t> count = feeders_.back()->selected_count();
    if (total && count) {
      *total += *count;
    } else {
      total.reset();
    }
  }
  if (total && params_.max_frames > 0) *total = std::min(*total, params_.max_frames);
  total_frames_ = total;
}

NegativeMiner::~NegativeMiner() = default;

MineStats mine_negatives(const MineParams& params, SampleSetWriter& out,
                         const std::function<void(const MineStats&)>& on_frame) {
  return NegativeMiner(params).run(out, on_frame);
}

MineStats NegativeMiner::run(SampleSetWriter& out, const std::function<void(const MineStats&)>& on_frame) {
  const MineParams& params = params_;
  const FrameAnalyser analyser(params.analyser);
  if (analyser.params().features != out.manifest().feature_spec) {
    fail(out.dir(), feature_spec_mismatch("sample set feature spec", out.manifest().feature_spec,
                                          "the detector's", analyser.params().features));
  }
  const int workers = resolve_thread_count(params.threads);

  MineStats stats;
  stats.total_frames = total_frames_;
  std::int64_t negatives = static_cast<std::int64_t>(
      std::count_if(out.records().begin(), out.records().end(), [](const SampleRecord& r) { return r.label == 0; }));
  std::int64_t frames_left =
      params.max_frames > 0 ? params.max_frames : std::numeric_limits<std::int64_t>::max();
  if (params.max_negatives > 0 && negatives >= params.max_negatives) {
    stats.reached_max = true;
    return stats;
  }
  if (on_frame) on_frame(stats);  // frames 0: the start, with the total known

  // Group commit (MineParams::sync_every_frames): frames are reported once their samples are on disk.
  const std::int64_t sync_every = params.sync_every_frames;
  std::int64_t unflushed_frames = 0;
  const auto flush = [&] {
    if (out.unsynced_rows() > 0) out.sync();
    unflushed_frames = 0;
    if (on_frame) on_frame(stats);
  };

  for (std::size_t s = 0; s < params.sources.size() && frames_left > 0 && !stats.reached_max; ++s) {
    const std::string name = sample_source(params.sources[s]);  // the one rule (sample_source.hpp)
    FrameFeeder& feeder = *feeders_[s];
    feeder.set_limit(frames_left);

    // Frames analysed on the workers, written here in frame order (ordered_map), flushed in groups.
    try {
      ordered_map<FrameFeeder::Job>(
          workers, 4 * static_cast<std::size_t>(workers),
          [&](FrameFeeder::Job& job) { return feeder.claim(job); },
          [&](FrameFeeder::Job& job) { return analyse_frame(analyser, params, name, feeder.load(job)); },
          [&](FrameResult result) {
            for (MinedCandidate& m : result.items) {
              ++stats.candidates;
              if (m.below_score) {
                ++stats.below_score;
                continue;
              }
              if (stats.reached_max) continue;
              if (out.is_duplicate(m.record)) {
                ++stats.duplicates;
                continue;
              }
              out.append_encoded(m.record, m.crop, /*sync=*/false);  // flushed with its group, below
              ++stats.kept;
              ++negatives;
              if (params.max_negatives > 0 && negatives >= params.max_negatives) stats.reached_max = true;
            }
            ++stats.frames;
            --frames_left;
            ++unflushed_frames;
            if (unflushed_frames >= sync_every || out.unsynced_rows() == 0 || stats.reached_max) flush();
            return !stats.reached_max;
          });
    } catch (...) {
      try {  // keep what was written (best effort: a failed write leaves the writer unusable anyway)
        if (out.unsynced_rows() > 0) out.sync();
      } catch (...) {
      }
      throw;
    }
  }
  if (unflushed_frames > 0) flush();
  return stats;
}

}  // namespace rdsf
