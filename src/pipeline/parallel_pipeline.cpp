#include "rdsf/pipeline/parallel_pipeline.hpp"

#include <utility>

#include "rdsf/core/error.hpp"
#include "rdsf/core/ordered_pool.hpp"

namespace rdsf {
namespace {

struct Analysed {
  DepthFrame frame;
  PipelineFrame result;
};

/// The one loop behind both entry points: `claim` reads the next frame in frame order as far as it must be
/// read in order, its decode() makes the frame on a worker.
std::int64_t run_jobs(PeoplePipeline& pipeline, const ParallelParams& params,
                      const std::function<bool(FrameDecode&)>& claim, const PipelineCallback& on_frame) {
  const PeoplePipeline& analyser = pipeline;  // analyse() is const: safe on every worker
  std::int64_t handed = 0, claimed = 0;
  ordered_map<FrameDecode>(
      params.threads, params.frames_ahead > 0 ? params.frames_ahead : default_items_ahead(params.threads),
      [&](FrameDecode& decode) {
        if (params.max_frames > 0 && claimed >= params.max_frames) return false;
        ++claimed;
        return claim(decode);
      },
      [&](FrameDecode& decode) {
        Analysed a;
        a.frame = decode();
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
      [&](FrameDecode& decode) {
        if (next >= count) return false;
        decode = [&load, i = next++] { return load(i); };
        return true;
      },
      on_frame);
}

std::int64_t run_in_frame_order(PeoplePipeline& pipeline, FrameSource& source, const CameraModel& camera,
                                const ParallelParams& params, const PipelineCallback& on_frame) {
  (void)camera;  // the source's own (a folder's camera.yml, a bag's CameraInfo, or the model it was opened with)
  return run_jobs(pipeline, params, [&](FrameDecode& decode) { return source.next_deferred(decode); }, on_frame);
}

}  // namespace rdsf
