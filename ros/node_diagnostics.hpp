#pragma once
// The node's health, published on /diagnostics (diagnostic_msgs/DiagnosticArray, one DiagnosticStatus
// "rdsf_people: people detection") every period and printed once at the end:
//   counts since the start: depth images received, refused (bad encoding, size, camera_info), processed,
//     dropped by the live pipeline (a newer frame took their place: newest frame wins), frames paired with
//     colour and without;
//   per period and since the start: latency from the depth message's arrival in the node to its people
//     published (p50, p95, p99, max, nearest rank), the colour pairing gap (max); since the start also
//     the part of it after the frame was complete (its colour in: without colour the same figure), i.e.
//     without the wait for the colour image.
// Level: OK; WARN when frames were dropped or refused in the period, p99 of the period exceeds the target,
// or no depth image arrived in the period. Thread-safe (workers publish, the timer reports).
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>

#include "rdsf/pipeline/live_pipeline.hpp"

namespace rdsf {

class NodeDiagnostics {
 public:
  explicit NodeDiagnostics(double target_p99_ms = 10.0) : target_p99_ms_(target_p99_ms) {}

  void received();
  void refused(const std::string& reason);
  /// A frame goes on to the pipeline: paired with colour at this gap (us), or -1 without colour.
  void paired(std::int64_t gap_us);
  /// A frame's people were published, `latency_ms` after its depth message arrived and `after_complete_ms`
  /// after the frame was complete (its colour image in).
  void published(double latency_ms, double after_complete_ms);

  /// The status of the period since the last report (and the counts since the start); starts a new period.
  diagnostic_msgs::DiagnosticArray report(const LiveStats& live, const std::string& hardware_id, double period_s);
  /// One line for the end: counts and latency percentiles since the start.
  std::string summary(const LiveStats& live) const;

 private:
  mutable std::mutex mutex_;
  double target_p99_ms_;
  std::int64_t received_ = 0, refused_ = 0, with_colour_ = 0, without_colour_ = 0;
  std::int64_t period_received_ = 0, period_refused_ = 0, dropped_at_last_report_ = 0;
  std::int64_t period_max_gap_us_ = -1, max_gap_us_ = -1;
  std::string last_refusal_;
  std::vector<double> latency_ms_, period_latency_ms_, after_complete_ms_;
};

}  // namespace rdsf
