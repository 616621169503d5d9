#include "rdsf/core/thread_count.hpp"

#include <thread>

namespace rdsf {

int resolve_thread_count(int requested) {
  if (requested > 0) return requested;
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware == 0 ? 1 : static_cast<int>(hardware);
}

}  // namespace rdsf
