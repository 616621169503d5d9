#include "rdsf/core/ordered_pool.hpp"

#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rdsf::detail {

namespace {

// One run of the pool: the state its threads share under `mutex`, and what each kind of thread does.
class OrderedRun {
 public:
  OrderedRun(std::size_t ahead, const std::function<bool(std::size_t)>& claim,
             const std::function<void(std::size_t)>& work)
      : ahead_(ahead), claim_(claim), work_(work), done_(ahead, 0) {}

  // A pool thread: claims and works items while there are any.
  void worker() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
      changed_.wait(lock, [&] { return stop_ || end_ || claimable(); });
      if (stop_ || end_ || !take_one(lock)) return;
    }
  }

  // The calling thread: waits for item `seq`'s result, working items itself meanwhile. Returns false when
  // there is none (claim ended, or an item up to `seq` failed: `met` is then that failure).
  bool wait_for(std::size_t seq, std::exception_ptr& met) {
    const std::size_t slot = seq % ahead_;
    std::unique_lock<std::mutex> lock(mutex_);
    // Items before a failure are all claimed and finish (their workers complete them). While the next
    // result is not ready the calling thread works an item itself (it is one of the `threads`).
    const auto ready = [&] { return done_[slot] || (failure_ && failure_seq_ <= seq) || (end_ && seq == claimed_); };
    while (!ready()) {
      if (claimable()) {
        take_one(lock);
      } else {
        changed_.wait(lock);
      }
    }
    if (!done_[slot]) {
      if (failure_ && failure_seq_ <= seq) met = failure_;
      return false;
    }
    done_[slot] = 0;
    return true;
  }

  // An item's result was consumed: its slot is free.
  void consumed() {
    std::lock_guard<std::mutex> lock(mutex_);
    ++consumed_;
    changed_.notify_all();
  }

  // No more claims (the consumer stopped, or is done).
  void stop() {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
    changed_.notify_all();
  }

 private:
  bool claimable() const { return !stop_ && !end_ && !claiming_ && claimed_ < consumed_ + ahead_; }

  void fail_locked(std::exception_ptr e, std::size_t seq) {
    if (!failure_ || seq < failure_seq_) {
      failure_ = std::move(e);
      failure_seq_ = seq;
    }
    stop_ = true;
    changed_.notify_all();
  }

  // Claims the next item and works it, on whichever thread calls it: with the lock held and an item
  // claimable; returns with the lock held, false when there was nothing more to claim or the item failed.
  bool take_one(std::unique_lock<std::mutex>& lock) {
    const std::size_t seq = claimed_;
    const std::size_t slot = seq % ahead_;  // free: its previous item was consumed
    claiming_ = true;
    lock.unlock();
    bool got = false;
    std::exception_ptr error;
    try {
      got = claim_(slot);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    claiming_ = false;
    if (error) {
      fail_locked(error, seq);  // notifies
      return false;
    }
    end_ = !got;
    changed_.notify_all();
    if (end_) return false;
    ++claimed_;
    lock.unlock();
    try {
      work_(slot);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    if (error) {
      fail_locked(error, seq);
      return false;
    }
    done_[slot] = 1;
    changed_.notify_all();
    return true;
  }

  const std::size_t ahead_;
  const std::function<bool(std::size_t)>& claim_;
  const std::function<void(std::size_t)>& work_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::size_t claimed_ = 0;   // items claimed so far (the next item's sequence number)
  std::size_t consumed_ = 0;  // items consumed so far
  std::vector<char> done_;    // per slot: its item's result is ready
  bool end_ = false;          // claim said there is nothing more
  bool stop_ = false;         // no more claims: the consumer stopped, or an item failed
  bool claiming_ = false;     // a worker is in claim(): one claim at a time, without holding the lock
  // The failure of the earliest item that failed: the consumer meets it where the one-thread loop would
  // (after every earlier item) and rethrows it; a failure beyond where the consumer stopped is never met.
  std::exception_ptr failure_;
  std::size_t failure_seq_ = 0;
};

}  // namespace

void run_ordered_pool(int threads, std::size_t ahead, const std::function<bool(std::size_t)>& claim,
                      const std::function<void(std::size_t)>& work, const std::function<bool(std::size_t)>& consume) {
  OrderedRun run(ahead, claim, work);
  std::exception_ptr met;  // what the consumer ran into
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads));
  try {
    for (int t = 1; t < threads; ++t) pool.emplace_back([&run] { run.worker(); });
    for (std::size_t seq = 0;; ++seq) {
      if (!run.wait_for(seq, met)) break;
      const bool go = consume(seq % ahead);
      run.consumed();
      if (!go) break;
    }
  } catch (...) {
    met = std::current_exception();
  }
  run.stop();
  for (std::thread& t : pool) t.join();
  if (met) std::rethrow_exception(met);
}

}  // namespace rdsf::detail
