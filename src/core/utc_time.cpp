#include "core/utc_time.hpp"

#include <ctime>

namespace rdsf {

std::string utc_now(const char* format) {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[64];
  return std::strftime(text, sizeof text, format, &utc) > 0 ? std::string(text) : std::string();
}

}  // namespace rdsf
