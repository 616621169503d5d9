#pragma once
// Memory per phase from /proc/self/status: VmRSS now and VmHWM (the peak resident set). Writing "5" to
// /proc/self/clear_refs resets the peak to the current resident set (Linux 4.0 and later), so each phase's
// peak is measured on its own.
namespace rdsf::perf {

struct MemoryMark {
  double rss_mib = 0;   ///< resident at the start of the phase
  bool reset = false;   ///< the peak was reset (false: the peak is the process's since its start)
};

/// Resets the peak and returns the resident set now.
MemoryMark start_memory_phase();
/// VmHWM in MiB (0 when /proc is unreadable).
double peak_rss_mib();
/// VmRSS in MiB.
double current_rss_mib();

}  // namespace rdsf::perf
