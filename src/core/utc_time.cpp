#include "rdsf/core/utc_time.hpp"

#include <cstdlib>
#include <ctime>

namespace rdsf {

std::string utc_now(const char* format) {
  std::time_t now = std::time(nullptr);
  // Reproducible outputs (the reproducible-builds convention): a fixed clock from SOURCE_DATE_EPOCH.
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"); epoch != nullptr && *epoch != '\0') {
    char* end = nullptr;
    const long long seconds = std::strtoll(epoch, &end, 10);
    if (end != nullptr && *end == '\0' && seconds >= 0) now = static_cast<std::time_t>(seconds);
  }
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[64];
  return std::strftime(text, sizeof text, format, &utc) > 0 ? std::string(text) : std::string();
}

}  // namespace rdsf
