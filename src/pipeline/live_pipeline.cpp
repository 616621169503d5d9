#include "rdsf/pipeline/live_pipeline.hpp"

#include <algorithm>
#include <cmath>

#include "rdsf/core/error.hpp"

namespace rdsf {

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  // Nearest rank: the smallest value with at least p % of the values at or below it.
  const double rank = std::ceil(p / 100.0 * static_cast<double>(values.size()));
  const std::size_t k = static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(values.size())));
  return values[k - 1];
}

LivePipeline::LivePipeline(PeoplePipeline& pipeline, LiveParams params, const Clock& clock, Output on_frame)
    : pipeline_(pipeline),
      params_(params),
      clock_(clock),
      on_frame_(std::move(on_frame)),
      capacity_(static_cast<std::size_t>(std::max(1, params.workers))) {
  if (params_.workers < 0) throw Error("live mode: workers must be 0 or more, got " + std::to_string(params_.workers));
  for (int t = 0; t < params_.workers; ++t) threads_.emplace_back([this] { worker(); });
}

LivePipeline::~LivePipeline() {
  try {
    finish();
  } catch (...) {  // reported by an earlier call, or lost with the object
  }
}

void LivePipeline::rethrow_failure_locked() {
  if (failure_) std::rethrow_exception(failure_);
}

void LivePipeline::push(DepthFrame frame) {
  const std::int64_t now = clock_.now_us();
  std::lock_guard<std::mutex> lock(mutex_);
  rethrow_failure_locked();
  if (stopping_) throw Error("live mode: push() after finish()");
  ++arrived_;
  if (queue_.size() >= capacity_) {  // newest frame wins
    queue_.pop_front();
    ++dropped_;
  }
  queue_.push_back({std::move(frame), now});
  changed_.notify_all();
}

bool LivePipeline::run_queued() {
  if (params_.workers != 0) throw Error("live mode: run_queued() is for workers = 0 (the workers take frames themselves)");
  Waiting w;
  std::uint64_t seq = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    rethrow_failure_locked();
    if (queue_.empty()) return false;
    w = std::move(queue_.front());
    queue_.pop_front();
    seq = taken_++;
  }
  process(std::move(w), seq);
  std::lock_guard<std::mutex> lock(mutex_);
  rethrow_failure_locked();
  return true;
}

void LivePipeline::worker() {
  while (true) {
    Waiting w;
    std::uint64_t seq = 0;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return !queue_.empty() || stopping_; });
      if (queue_.empty()) return;  // stopping, nothing left
      w = std::move(queue_.front());
      queue_.pop_front();
      seq = taken_++;
      changed_.notify_all();  // queued() went down
    }
    process(std::move(w), seq);
  }
}

void LivePipeline::process(Waiting w, std::uint64_t seq) {
  std::exception_ptr error;
  PipelineFrame result;
  try {
    result = static_cast<const PeoplePipeline&>(pipeline_).analyse(w.frame);  // in parallel
  } catch (...) {
    error = std::current_exception();
  }
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return out_ == seq; });  // frames taken earlier are out
  if (!error && !failure_) {
    lock.unlock();  // only this frame's worker tracks now: the others wait for their turn above
    try {
      pipeline_.track(w.frame, result);
      const std::int64_t latency_us = clock_.now_us() - w.arrival_us;
      if (on_frame_) on_frame_(w.frame, result, latency_us);
      lock.lock();
      latency_ms_.push_back(static_cast<double>(latency_us) / 1000.0);
    } catch (...) {
      if (!lock.owns_lock()) lock.lock();
      error = std::current_exception();
    }
  }
  if (error && !failure_) failure_ = error;
  ++out_;
  changed_.notify_all();
}

void LivePipeline::finish() {
  if (params_.workers == 0) {
    while (run_queued()) {
    }
  }
  {
    std::unique_lock<std::mutex> lock(mutex_);
    if (params_.workers > 0) {
      changed_.wait(lock, [&] { return (queue_.empty() && out_ == taken_) || failure_; });
    }
    stopping_ = true;
    changed_.notify_all();
  }
  for (std::thread& t : threads_) {
    if (t.joinable()) t.join();
  }
  threads_.clear();
  std::lock_guard<std::mutex> lock(mutex_);
  rethrow_failure_locked();
}

std::size_t LivePipeline::queued() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return queue_.size();
}

LiveStats LivePipeline::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  LiveStats s;
  s.arrived = arrived_;
  s.dropped = dropped_;
  s.processed = static_cast<std::int64_t>(latency_ms_.size());
  s.p50_ms = percentile(latency_ms_, 50);
  s.p95_ms = percentile(latency_ms_, 95);
  s.p99_ms = percentile(latency_ms_, 99);
  s.max_ms = latency_ms_.empty() ? 0.0 : *std::max_element(latency_ms_.begin(), latency_ms_.end());
  return s;
}

}  // namespace rdsf
