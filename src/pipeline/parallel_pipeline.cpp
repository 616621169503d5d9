#include "rdsf/pipeline/parallel_pipeline.hpp"

#include <utility>

#include "rdsf/core/error.hpp"
#include "rdsf/core/ordered_pool.hpp"
#include "rdsf/frame/png_folder_source.hpp"

namespace rdsf {
namespace {

/// A claimed frame: its index (to load on a worker) or the frame itself (read by claim).
struct FrameJob {
  std::int64_t index = 0;
  DepthFrame frame;
  bool read = false;
};

struct Analysed {
  DepthFrame frame;
  PipelineFrame result;
};

/// The one loop behind the three entry points: `claim` fills a job in frame order, `load` makes a job's
/// frame on a worker.
std::int64_t run_jobs(PeoplePipeline& pipeline, const ParallelParams& params,
                      const std::function<bool(FrameJob&)>& claim, const std::function<DepthFrame(FrameJob&)>& load,
                      const PipelineCallback& on_frame) {
  const PeoplePipeline& analyser = pipeline;  // analyse() is const: safe on every worker
  std::int64_t handed = 0, claimed = 0;
  ordered_map<FrameJob>(
      params.threads, params.frames_ahead > 0 ? params.frames_ahead : default_items_ahead(params.threads),
      [&](FrameJob& job) {
        if (params.max_frames > 0 && claimed >= params.max_frames) return false;
        ++claimed;
        return claim(job);
      },
      [&](FrameJob& job) {
        Analysed a;
        a.frame = job.read ? std::move(job.frame) : load(job);
        a.result = analyser.analyse(a.frame);
        return a;
      },
      [&](Analysed a) {
        pipeline.track(a.frame, a.result);
        ++handed;
        return !on_frame || on_frame(a.frame, a.result);
      });
  return handed;
}

}  // namespace

std::int64_t run_in_frame_order(PeoplePipeline& pipeline, std::int64_t count,
                                const std::function<DepthFrame(std::int64_t)>& load, const ParallelParams& params,
                                const PipelineCallback& on_frame) {
  std::int64_t next = 0;
  return run_jobs(
      pipeline, params,
      [&](FrameJob& job) {
        if (next >= count) return false;
        job.index = next++;
        return true;
      },
      [&](FrameJob& job) { return load(job.index); }, on_frame);
}

std::int64_t run_in_frame_order(PeoplePipeline& pipeline, FrameSource& source, const CameraModel& camera,
                                const ParallelParams& params, const PipelineCallback& on_frame) {
  const auto* folder = dynamic_cast<const PngFolderSource*>(&source);
  if (folder == nullptr) {
    return run_jobs(
        pipeline, params,
        [&](FrameJob& job) {
          if (!source.next(job.frame)) return false;
          job.read = true;
          return true;
        },
        {}, on_frame);
  }
  // Each frame's files read on a worker: the same frame PngFolderSource delivers as frame i.
  (void)camera;  // the folder's own (its camera.yml or the model it was opened with)
  auto load = [folder](std::int64_t i) { return folder->read_frame(static_cast<std::size_t>(i)); };
  return run_in_frame_order(pipeline, static_cast<std::int64_t>(folder->depth_paths().size()), load, params,
                            on_frame);
}

}  // namespace rdsf
