#include "rdsf/core/frame_buffers.hpp"

#include <array>
#include <vector>

namespace rdsf {

cv::Mat frame_buffer(FrameBuffer use, cv::Size size, int type) {
  thread_local std::array<std::vector<cv::Mat>, static_cast<std::size_t>(FrameBuffer::last) + 1> pools;
  std::vector<cv::Mat>& pool = pools[static_cast<std::size_t>(use)];
  for (cv::Mat& kept : pool) {
    // 1: the pool's own reference alone. OpenCV changes the count atomically; read it so too.
    if (kept.u != nullptr && __atomic_load_n(&kept.u->refcount, __ATOMIC_ACQUIRE) == 1) {
      if (kept.size() != size || kept.type() != type) kept.create(size, type);  // the old buffer freed
      return kept;
    }
  }
  cv::Mat made(size, type);
  if (static_cast<int>(pool.size()) < kFrameBuffersPerUse) pool.push_back(made);
  return made;
}

}  // namespace rdsf
