#pragma once
// The whole system over many frames, analysed on N threads and tracked in frame order:
//   frames -> PeoplePipeline::analyse on threads 1..N -> PeoplePipeline::track in frame order -> on_frame
// built on the library's one ordered thread pool (core/ordered_pool.hpp). Tracking and on_frame run on the
// calling thread, frame after frame, so the results are bit for bit those of PeoplePipeline::process called
// frame after frame, whatever the thread count (threads 1 runs exactly that loop, without threads).
// At most frames_ahead frames are in memory at once (read and not yet handed to on_frame).
#include <cstdint>
#include <functional>

#include "rdsf/frame/camera_model.hpp"
#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"

namespace rdsf {

struct ParallelParams {
  int threads = 0;               ///< workers analysing frames (0: one per core, resolve_thread_count)
  std::size_t frames_ahead = 0;  ///< frames read ahead of tracking (0: 2 per thread + 2)
  std::int64_t max_frames = 0;   ///< stop after this many frames, none read beyond (0: every frame)
};

/// Called on the calling thread for each frame, in frame order, after tracking; return false to stop.
using PipelineCallback = std::function<bool(const DepthFrame& frame, PipelineFrame& result)>;

/// Runs over every frame of `source` (no frame read from it yet): read in order, one read at a time, as far as
/// FrameSource::next_deferred reads, and decoded on the workers (image folders and list files each frame from
/// its own files, bags each frame's messages; devices and .oni files are read whole in order): the same frames
/// the source delivers. `camera` is not used (the sources carry their own since issue 36). Returns the number
/// of frames handed to on_frame.
std::int64_t run_in_frame_order(PeoplePipeline& pipeline, FrameSource& source, const CameraModel& camera,
                                const ParallelParams& params, const PipelineCallback& on_frame);

/// Runs over frames 0 .. count-1 made by load(i), called on the workers (concurrently: it must be
/// thread-safe), e.g. frames in memory.
std::int64_t run_in_frame_order(PeoplePipeline& pipeline, std::int64_t count,
                                const std::function<DepthFrame(std::int64_t)>& load, const ParallelParams& params,
                                const PipelineCallback& on_frame);

}  // namespace rdsf
