#pragma once
// Runs fn(begin, end) over [0, n) split into one contiguous chunk per thread (std::thread). Each index is
// handled by exactly one call, so work that writes per-index results is deterministic whatever the
// thread count.
#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace rdsf {

/// Number of threads to use: `requested` when positive, else the hardware's count (at least 1).
inline int resolve_thread_count(int requested) {
  if (requested > 0) return requested;
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware == 0 ? 1 : static_cast<int>(hardware);
}

template <typename Fn>
void parallel_chunks(std::size_t n, int threads, Fn&& fn) {
  const std::size_t parts = std::min<std::size_t>(static_cast<std::size_t>(std::max(1, threads)), n);
  if (parts <= 1) {
    if (n > 0) fn(std::size_t{0}, n);
    return;
  }
  std::vector<std::thread> workers;
  workers.reserve(parts - 1);
  const std::size_t step = (n + parts - 1) / parts;
  for (std::size_t p = 1; p < parts; ++p) {
    const std::size_t begin = std::min(n, p * step), end = std::min(n, begin + step);
    workers.emplace_back([&fn, begin, end] {
      if (begin < end) fn(begin, end);
    });
  }
  fn(std::size_t{0}, std::min(n, step));
  for (auto& worker : workers) worker.join();
}

}  // namespace rdsf
