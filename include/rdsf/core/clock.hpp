#pragma once
// A clock that can be replaced: what live mode reads to time frames (arrival to detections out), so tests
// drive time by hand instead of sleeping. Times are microseconds from an arbitrary origin, never decreasing.
#include <atomic>
#include <cstdint>

namespace rdsf {

class Clock {
 public:
  virtual ~Clock() = default;
  /// Microseconds since an arbitrary origin; never decreases. Thread-safe.
  virtual std::int64_t now_us() const = 0;
};

/// std::chrono::steady_clock.
class SteadyClock : public Clock {
 public:
  std::int64_t now_us() const override;
};

/// A clock that only moves when told (tests). Thread-safe.
class ManualClock : public Clock {
 public:
  explicit ManualClock(std::int64_t start_us = 0) : now_(start_us) {}
  std::int64_t now_us() const override { return now_.load(); }
  void set_us(std::int64_t t_us) { now_.store(t_us); }
  void advance_us(std::int64_t dt_us) { now_.fetch_add(dt_us); }

 private:
  std::atomic<std::int64_t> now_;
};

}  // namespace rdsf
