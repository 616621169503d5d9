#include "ros/node_diagnostics.hpp"

#include <algorithm>
#include <cstdio>

#include <ros/time.h>

namespace rdsf {
namespace {

std::string fixed(double value, int decimals = 2) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

diagnostic_msgs::KeyValue key_value(const std::string& key, const std::string& value) {
  diagnostic_msgs::KeyValue kv;
  kv.key = key;
  kv.value = value;
  return kv;
}

}  // namespace

void NodeDiagnostics::received() {
  const std::lock_guard<std::mutex> lock(mutex_);
  ++received_;
  ++period_received_;
}

void NodeDiagnostics::refused(const std::string& reason) {
  const std::lock_guard<std::mutex> lock(mutex_);
  ++refused_;
  ++period_refused_;
  last_refusal_ = reason;
}

void NodeDiagnostics::paired(std::int64_t gap_us) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (gap_us < 0) {
    ++without_colour_;
    return;
  }
  ++with_colour_;
  period_max_gap_us_ = std::max(period_max_gap_us_, gap_us);
  max_gap_us_ = std::max(max_gap_us_, gap_us);
}

void NodeDiagnostics::published(double latency_ms, double after_complete_ms) {
  const std::lock_guard<std::mutex> lock(mutex_);
  latency_ms_.push_back(latency_ms);
  after_complete_ms_.push_back(after_complete_ms);
  period_latency_ms_.push_back(latency_ms);
}

diagnostic_msgs::DiagnosticArray NodeDiagnostics::report(const LiveStats& live, const std::string& hardware_id,
                                                         double period_s) {
  const std::lock_guard<std::mutex> lock(mutex_);
  diagnostic_msgs::DiagnosticStatus status;
  status.name = "rdsf_people: people detection";
  status.hardware_id = hardware_id;
  const std::int64_t period_dropped = live.dropped - dropped_at_last_report_;
  const double p50 = percentile(period_latency_ms_, 50), p95 = percentile(period_latency_ms_, 95);
  const double p99 = percentile(period_latency_ms_, 99), max = percentile(period_latency_ms_, 100);
  const double rate = period_s > 0 ? static_cast<double>(period_latency_ms_.size()) / period_s : 0.0;
  std::string message = fixed(rate, 1) + " frames/s published, " + std::to_string(period_dropped) + " dropped, " +
                        std::to_string(period_refused_) + " refused; latency p50 " + fixed(p50) + " ms, p99 " +
                        fixed(p99) + " ms";
  status.level = diagnostic_msgs::DiagnosticStatus::OK;
  if (period_received_ == 0) {
    status.level = diagnostic_msgs::DiagnosticStatus::WARN;
    message = "no depth image in the last " + fixed(period_s, 1) + " s";
  } else if (period_dropped > 0 || period_refused_ > 0 || p99 > target_p99_ms_) {
    status.level = diagnostic_msgs::DiagnosticStatus::WARN;
    if (period_refused_ > 0) message += " (last refusal: " + last_refusal_ + ")";
  }
  status.message = message;
  status.values = {
      key_value("depth images received", std::to_string(received_)),
      key_value("depth images refused", std::to_string(refused_)),
      key_value("frames processed", std::to_string(live.processed)),
      key_value("frames dropped", std::to_string(live.dropped)),
      key_value("frames with colour", std::to_string(with_colour_)),
      key_value("frames without colour", std::to_string(without_colour_)),
      key_value("period s", fixed(period_s, 3)),
      key_value("period frames published", std::to_string(period_latency_ms_.size())),
      key_value("period frames dropped", std::to_string(period_dropped)),
      key_value("period latency p50 ms", fixed(p50, 3)),
      key_value("period latency p95 ms", fixed(p95, 3)),
      key_value("period latency p99 ms", fixed(p99, 3)),
      key_value("period latency max ms", fixed(max, 3)),
      key_value("period colour gap max ms", period_max_gap_us_ < 0 ? "-" : fixed(static_cast<double>(period_max_gap_us_) / 1000.0, 3)),
      key_value("latency p50 ms", fixed(percentile(latency_ms_, 50), 3)),
      key_value("latency p99 ms", fixed(percentile(latency_ms_, 99), 3)),
      key_value("latency max ms", fixed(percentile(latency_ms_, 100), 3)),
      key_value("after complete p99 ms", fixed(percentile(after_complete_ms_, 99), 3)),
      key_value("latency target p99 ms", fixed(target_p99_ms_, 1)),
  };
  diagnostic_msgs::DiagnosticArray array;
  array.header.stamp = ros::Time::now();
  array.status.push_back(status);
  period_latency_ms_.clear();
  period_received_ = 0;
  period_refused_ = 0;
  period_max_gap_us_ = -1;
  dropped_at_last_report_ = live.dropped;
  return array;
}

std::string NodeDiagnostics::summary(const LiveStats& live) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return std::to_string(received_) + " depth images received, " + std::to_string(refused_) + " refused, " +
         std::to_string(live.processed) + " processed, " + std::to_string(live.dropped) + " dropped; " +
         std::to_string(with_colour_) + " with colour (largest gap " +
         (max_gap_us_ < 0 ? std::string("-") : fixed(static_cast<double>(max_gap_us_) / 1000.0, 3) + " ms") + "), " +
         std::to_string(without_colour_) + " without; latency message to people published p50 " +
         fixed(percentile(latency_ms_, 50)) + " ms, p95 " + fixed(percentile(latency_ms_, 95)) + " ms, p99 " +
         fixed(percentile(latency_ms_, 99)) + " ms, max " + fixed(percentile(latency_ms_, 100)) +
         " ms; after the frame was complete (colour in) p50 " + fixed(percentile(after_complete_ms_, 50)) + " ms, p95 " +
         fixed(percentile(after_complete_ms_, 95)) + " ms, p99 " + fixed(percentile(after_complete_ms_, 99)) +
         " ms, max " + fixed(percentile(after_complete_ms_, 100)) + " ms";
}

}  // namespace rdsf
