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
  bool stop = false;         // no more claims: the consumer stopped, or an item failed
  bool claiming = false;     // a worker is in claim(): one claim at a time, without holding the lock
  // The failure of the earliest item that failed: the consumer meets it where the one-thread loop would
  // (after every earlier item) and rethrows it; a failure beyond where the consumer stopped is never met.
  std::exception_ptr failure;
  std::size_t failure_seq = 0;
  auto fail_locked = [&](std::exception_ptr e, std::size_t seq) {
    if (!failure || seq < failure_seq) {
      failure = std::move(e);
      failure_seq = seq;
    }
    stop = true;
    changed.notify_all();
  };

  // Claims the next item and works it, on whichever thread calls it: with the lock held and an item
  // claimable (!claiming, claimed < consumed + ahead, !stop, !end); returns with the lock held, false when
  // there was nothing more to claim or the item failed.
  auto take_one = [&](std::unique_lock<std::mutex>& lock) {
    const std::size_t seq = claimed;
    const std::size_t slot = seq % ahead;  // free: its previous item was consumed
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
    if (error) {
      fail_locked(error, seq);  // notifies
      return false;
    }
    end = !got;
    changed.notify_all();
    if (end) return false;
    ++claimed;
    lock.unlock();
    try {
      work(slot);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    if (error) {
      fail_locked(error, seq);
      return false;
    }
    done[slot] = 1;
    changed.notify_all();
    return true;
  };
  const auto claimable = [&] { return !stop && !end && !claiming && claimed < consumed + ahead; };

  auto worker = [&] {
    std::unique_lock<std::mutex> lock(mutex);
    while (true) {
      changed.wait(lock, [&] { return stop || end || claimable(); });
      if (stop || end || !take_one(lock)) return;
    }
  };

  std::exception_ptr met;  // what the consumer ran into
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads));
  try {
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    for (std::size_t seq = 0;; ++seq) {
      const std::size_t slot = seq % ahead;
      {
        std::unique_lock<std::mutex> lock(mutex);
        // Items before a failure are all claimed and finish (their workers complete them). While the next
        // result is not ready the calling thread works an item itself (it is one of the `threads`).
        const auto ready = [&] { return done[slot] || (failure && failure_seq <= seq) || (end && seq == claimed); };
        while (!ready()) {
          if (claimable()) {
            take_one(lock);
          } else {
            changed.wait(lock);
          }
        }
        if (!done[slot]) {
          if (failure && failure_seq <= seq) met = failure;
          break;
        }
        done[slot] = 0;
      }
      const bool go = consume(slot);
      std::lock_guard<std::mutex> lock(mutex);
      ++consumed;
      changed.notify_all();
      if (!go) break;
    }
  } catch (...) {
    met = std::current_exception();
  }
  {
    std::lock_guard<std::mutex> lock(mutex);
    stop = true;
    changed.notify_all();
  }
  for (std::thread& t : pool) t.join();
  if (met) std::rethrow_exception(met);
}

}  // namespace rdsf::detail
