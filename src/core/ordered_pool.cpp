#include "rdsf/core/ordered_pool.hpp"

#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

namespace rdsf::detail {

void run_ordered_pool(int threads, std::size_t ahead, const std::function<bool(std::size_t)>& claim,
                      const std::function<void(std::size_t)>& work, const std::function<bool(std::size_t)>& consume) {
  std::mutex mutex;
  std::condition_variable changed;
  std::size_t claimed = 0;   // items claimed so far (the next item's sequence number)
  std::size_t consumed = 0;  // items consumed so far
  std::vector<char> done(ahead, 0);  // per slot: its item's result is ready
  bool end = false;          // claim said there is nothing more
  bool stop = false;         // the consumer stopped, or something failed
  bool consumer_done = false;  // the consumer stopped: errors of items it will never see are not errors
  std::exception_ptr failure;
  auto fail_locked = [&](std::exception_ptr e) {
    if (!failure && !consumer_done) failure = std::move(e);
    stop = true;
    changed.notify_all();
  };

  // One worker claims at a time (`claiming`), without holding the lock: a claim that waits for a device's
  // next frame does not keep the consumer from taking finished results.
  bool claiming = false;
  auto worker = [&] {
    std::unique_lock<std::mutex> lock(mutex);
    while (true) {
      changed.wait(lock, [&] { return stop || end || (!claiming && claimed < consumed + ahead); });
      if (stop || end) return;
      const std::size_t slot = claimed % ahead;  // free: its previous item was consumed
      claiming = true;
      lock.unlock();
      bool got = false;
      std::exception_ptr error;
      try {
        got = claim(slot);
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      claiming = false;
      changed.notify_all();
      if (error) {
        fail_locked(error);
        return;
      }
      if (!got) {
        end = true;
        return;
      }
      ++claimed;
      lock.unlock();
      try {
        work(slot);
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      if (error) {
        fail_locked(error);
        return;
      }
      done[slot] = 1;
      changed.notify_all();
    }
  };

  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads));
  try {
    for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
    for (std::size_t seq = 0;; ++seq) {
      const std::size_t slot = seq % ahead;
      {
        std::unique_lock<std::mutex> lock(mutex);
        changed.wait(lock, [&] { return failure || done[slot] || (end && seq == claimed); });
        if (failure || !done[slot]) break;
        done[slot] = 0;
      }
      const bool go = consume(slot);
      std::lock_guard<std::mutex> lock(mutex);
      ++consumed;
      changed.notify_all();
      if (!go) {
        consumer_done = stop = true;
        break;
      }
    }
  } catch (...) {
    std::lock_guard<std::mutex> lock(mutex);
    fail_locked(std::current_exception());
  }
  {
    std::lock_guard<std::mutex> lock(mutex);
    consumer_done = !failure;  // from here on only items nobody will consume can fail
    stop = true;
    changed.notify_all();
  }
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace rdsf::detail
