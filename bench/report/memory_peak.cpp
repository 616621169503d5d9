#include "memory_peak.hpp"

#include <fstream>
#include <string>

namespace rdsf::perf {
namespace {

double status_mib(const char* key) {
  std::ifstream status("/proc/self/status");
  const std::string prefix = std::string(key) + ":";
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(prefix, 0) == 0) return std::stod(line.substr(prefix.size())) / 1024.0;  // kB
  }
  return 0.0;
}

}  // namespace

MemoryMark start_memory_phase() {
  MemoryMark mark;
  {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    clear.flush();
    mark.reset = static_cast<bool>(clear);
  }
  mark.rss_mib = current_rss_mib();
  return mark;
}

double peak_rss_mib() { return status_mib("VmHWM"); }
double current_rss_mib() { return status_mib("VmRSS"); }

}  // namespace rdsf::perf
