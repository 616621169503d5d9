#pragma once
// Runs fn(begin, end) over [0, n) split into one contiguous chunk per thread (std::thread). Each index is
// handled by exactly one call, so work that writes per-index results is deterministic whatever the
// thread count.
#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

#include "rdsf/core/thread_count.hpp"  // resolve_thread_count, for the callers

namespace rdsf {

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
