#pragma once
// Small helpers of the report's issue-17 sections (speed_limits.cpp, peer_training.cpp): wall and processor
// time, the load average, fixed-point numbers.
#include <sys/resource.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <string>

namespace rdsf::perf::clock {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// Processor time of the whole process (every thread), seconds.
inline double process_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/// "1.23 / 0.98 / 0.75" from /proc/loadavg, or "unknown".
inline std::string load_average_now() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a.empty() ? std::string("unknown") : a + " / " + b + " / " + c;
}

/// `v` with `digits` decimals.
inline std::string fixed(double v, int digits) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(digits);
  s << v;
  return s.str();
}

}  // namespace rdsf::perf::clock
