#pragma once
// Small helpers of the report's issue-17 sections (speed_limits.cpp, peer_training.cpp): wall and processor
// time, the load average, a reference loop for the machine's speed, fixed-point numbers.
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <cstdint>

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

/// The machine's speed now: processor time (ms, this thread) of a fixed chain of 2 * 10^7 dependent integer
/// steps (multiply, shift, xor), the best of 5 passes. It moves with the clock rate and with neighbours on
/// the same cores that the load average of this VM does not see; two runs' figures compare only when
/// their reference loops agree.
inline double reference_loop_ms() {
  double best = 1e300;
  for (int pass = 0; pass < 5; ++pass) {
    timespec a{}, b{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &a);
    std::uint64_t x = 0x9e3779b97f4a7c15ULL + static_cast<std::uint64_t>(pass);
    for (int i = 0; i < 20000000; ++i) {
      x *= 0xbf58476d1ce4e5b9ULL;
      x ^= x >> 31;
    }
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &b);
    volatile std::uint64_t sink = x;
    (void)sink;
    best = std::min(best, 1e3 * static_cast<double>(b.tv_sec - a.tv_sec) + 1e-6 * static_cast<double>(b.tv_nsec - a.tv_nsec));
  }
  return best;
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
