#pragma once
// Live (streaming) mode for a camera: frames arrive at the camera's rate (push, from the camera's thread);
// `workers` threads each analyse one frame at a time (PeoplePipeline::analyse) and the frames are tracked and
// handed to on_frame in arrival order, one at a time.
// Invariants:
//   - never more than one frame waits per worker (queue capacity = workers, 1 without threads): when a frame
//     arrives and the queue is full, the oldest waiting frame is dropped and counted (newest frame wins: a
//     robot wants the newest frame). A frame already being analysed is never dropped;
//   - push() never waits for analysis;
//   - latency of a frame = clock.now_us() when on_frame is called (after tracking: its detections are out)
//     minus clock.now_us() at its push(); stats() gives p50/p95/p99 by nearest rank over processed frames.
// The clock is an interface (core/clock.hpp): SteadyClock live, ManualClock in tests. With workers == 0
// nothing runs on its own: run_queued() processes the oldest waiting frame on the calling thread (a
// single-threaded loop, or a test that decides when the consumer has time).
// An exception from the pipeline or on_frame stops processing; push(), run_queued() and finish() rethrow it.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "rdsf/core/clock.hpp"
#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"

namespace rdsf {

struct LiveParams {
  int workers = 2;  ///< threads analysing frames; 0: none, the caller calls run_queued()
};

struct LiveStats {
  std::int64_t arrived = 0;    ///< frames pushed
  std::int64_t processed = 0;  ///< frames handed to on_frame
  std::int64_t dropped = 0;    ///< frames dropped while waiting (a newer frame took their place)
  double p50_ms = 0, p95_ms = 0, p99_ms = 0, max_ms = 0;  ///< latency, arrival to detections out
};

/// Nearest-rank percentile (0 < p <= 100) of `values` (any order); 0 when empty.
double percentile(std::vector<double> values, double p);

class LivePipeline {
 public:
  /// Called for each processed frame in arrival order, with its latency so far (microseconds).
  using Output = std::function<void(const DepthFrame& frame, PipelineFrame& result, std::int64_t latency_us)>;

  /// `pipeline` and `clock` must outlive this object; no other thread may use `pipeline` meanwhile.
  LivePipeline(PeoplePipeline& pipeline, LiveParams params, const Clock& clock, Output on_frame);
  ~LivePipeline();  ///< finish(), without rethrowing
  LivePipeline(const LivePipeline&) = delete;
  LivePipeline& operator=(const LivePipeline&) = delete;

  /// A frame arrives now (clock time). Queued, possibly dropping the oldest waiting frame.
  void push(DepthFrame frame);
  /// workers == 0 only: processes the oldest waiting frame here; false when none was waiting.
  bool run_queued();
  /// Waits until every waiting and running frame is processed and stops the workers (no push afterwards).
  void finish();

  /// Frames waiting (not yet taken by a worker).
  std::size_t queued() const;
  LiveStats stats() const;

 private:
  struct Waiting {
    DepthFrame frame;
    std::int64_t arrival_us = 0;
  };
  void worker();
  /// Analyses a taken frame, then tracks and outputs it when all frames taken before it are out.
  void process(Waiting w, std::uint64_t seq);
  void rethrow_failure_locked();

  PeoplePipeline& pipeline_;
  LiveParams params_;
  const Clock& clock_;
  Output on_frame_;
  std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Waiting> queue_;
  std::uint64_t taken_ = 0;     ///< frames taken from the queue (the next one's sequence number)
  std::uint64_t out_ = 0;       ///< frames done (tracked and output, or failed)
  bool stopping_ = false;
  std::exception_ptr failure_;
  std::int64_t arrived_ = 0, dropped_ = 0;
  std::vector<double> latency_ms_;
  std::vector<std::thread> threads_;
};

}  // namespace rdsf
