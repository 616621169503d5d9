// The library's one ordered thread pool (core/ordered_pool.hpp) and thread-count rule: results in claim
// order whatever the thread count, bounded look-ahead, the calling thread working too, early stop, errors
// passed on.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <cstdint>
#include <stdexcept>
#include <thread>
#include <vector>

#include "rdsf/core/error.hpp"
#include "rdsf/core/ordered_pool.hpp"
#include "rdsf/core/thread_count.hpp"

using namespace rdsf;

namespace {

/// Uneven deterministic work: item i spins for a while that varies with i (no sleeping).
std::uint64_t busy(std::size_t i) {
  std::uint64_t x = i + 1;
  const std::size_t rounds = 2000 + (i * 7919) % 50000;
  for (std::size_t k = 0; k < rounds; ++k) x = x * 6364136223846793005ull + 1442695040888963407ull;
  return x;
}

}  // namespace

TEST(ThreadCount, PositiveIsKeptZeroOrLessIsOnePerCore) {
  EXPECT_EQ(resolve_thread_count(3), 3);
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  EXPECT_EQ(resolve_thread_count(0), cores > 0 ? cores : 1);
  EXPECT_EQ(resolve_thread_count(-2), resolve_thread_count(0));
  EXPECT_GE(resolve_thread_count(0), 1);
}

TEST(OrderedPool, ResultsComeInClaimOrderWithBoundedLookAhead) {
  const std::size_t n = 300;
  std::vector<std::uint64_t> expected;
  for (std::size_t i = 0; i < n; ++i) expected.push_back(busy(i));
  for (int threads : {1, 2, 3, 8}) {
    for (std::size_t ahead : {std::size_t{1}, std::size_t{4}, std::size_t{16}}) {
      std::size_t next = 0, most_outstanding = 0;
      std::atomic<std::size_t> consumed{0};  // read by claim (a worker), written by consume
      std::atomic<int> running{0}, most_running{0};
      std::vector<std::uint64_t> got;
      ordered_map<std::size_t>(
          threads, ahead,
          [&](std::size_t& item) {  // called one at a time
            if (next >= n) return false;
            item = next++;
            most_outstanding = std::max(most_outstanding, next - consumed.load());
            return true;
          },
          [&](std::size_t& item) {
            const int now = ++running;
            int seen = most_running.load();
            while (now > seen && !most_running.compare_exchange_weak(seen, now)) {
            }
            const std::uint64_t v = busy(item);
            --running;
            return std::make_pair(item, v);
          },
          [&](std::pair<std::size_t, std::uint64_t> r) {
            EXPECT_EQ(r.first, got.size());
            got.push_back(r.second);
            ++consumed;
            return true;
          });
      EXPECT_EQ(got, expected) << threads << " threads, ahead " << ahead;
      EXPECT_LE(most_outstanding, std::max<std::size_t>(ahead, static_cast<std::size_t>(threads)));
      EXPECT_LE(most_running.load(), threads);
    }
  }
}

// `threads` threads work in all, the calling thread one of them (it works while the next result is not
// ready), so no extra thread competes with the workers for the cores.
TEST(OrderedPool, TheCallingThreadIsOneOfTheThreads) {
  for (int threads : {2, 3}) {
    std::mutex mutex;
    std::set<std::thread::id> working;
    std::size_t next = 0, consumed = 0;
    ordered_map<std::size_t>(
        threads, 16,
        [&](std::size_t& item) {
          if (next >= 200) return false;
          item = next++;
          return true;
        },
        [&](std::size_t& item) {
          {
            std::lock_guard<std::mutex> lock(mutex);
            working.insert(std::this_thread::get_id());
          }
          return busy(item);
        },
        [&](std::uint64_t) { return ++consumed > 0; });
    EXPECT_EQ(consumed, 200u);
    EXPECT_LE(working.size(), static_cast<std::size_t>(threads));
    EXPECT_EQ(working.count(std::this_thread::get_id()), 1u) << threads << " threads";
  }
}

TEST(OrderedPool, ConsumeFalseStopsAndNothingMoreIsConsumed) {
  for (int threads : {1, 4}) {
    std::size_t next = 0;
    std::vector<std::size_t> got;
    ordered_map<std::size_t>(
        threads, 8,
        [&](std::size_t& item) {
          if (next >= 1000) return false;
          item = next++;
          return true;
        },
        [](std::size_t& item) { return item; },
        [&](std::size_t item) {
          got.push_back(item);
          return item < 9;
        });
    EXPECT_EQ(got.size(), 10u) << threads;
    EXPECT_EQ(got.back(), 9u);
    EXPECT_LE(next, 10u + 8u) << "claims stop at the look-ahead";
  }
}

TEST(OrderedPool, ErrorsOfItemsBeyondAStopAreNotErrors) {
  // A device that times out after its last frame: the consumer stops at 5; claims beyond it fail, but the
  // one-thread loop would never have made them, so they are not errors.
  for (int threads : {1, 2, 4}) {
    std::size_t next = 0;
    std::vector<std::size_t> got;
    EXPECT_NO_THROW(ordered_map<std::size_t>(
        threads, 8,
        [&](std::size_t& item) {
          if (next >= 6) throw Error("device: no frame within 2000 ms");
          item = next++;
          return true;
        },
        [](std::size_t& item) { return item; },
        [&](std::size_t item) {
          got.push_back(item);
          return item < 5;
        }));
    EXPECT_EQ(got.size(), 6u);
  }
}

TEST(OrderedPool, FirstErrorOfClaimWorkOrConsumeIsRethrown) {
  for (int threads : {1, 3}) {
    auto run = [threads](int fail_in) {
      std::size_t next = 0;
      std::size_t consumed = 0;
      std::string message;
      try {
        ordered_map<std::size_t>(
            threads, 4,
            [&](std::size_t& item) {
              if (fail_in == 0 && next == 20) throw Error("claim failed");
              if (next >= 100) return false;
              item = next++;
              return true;
            },
            [&](std::size_t& item) {
              if (fail_in == 1 && item == 30) throw Error("work failed");
              return item;
            },
            [&](std::size_t item) {
              if (fail_in == 2 && item == 40) throw Error("consume failed");
              ++consumed;
              return true;
            });
      } catch (const Error& e) {
        message = e.what();
      }
      return std::make_pair(message, consumed);
    };
    // As the one-thread loop: every item before the failing one is consumed, none after it.
    EXPECT_EQ(run(0).first, "claim failed");
    EXPECT_EQ(run(0).second, 20u);
    EXPECT_EQ(run(1).first, "work failed");
    EXPECT_EQ(run(1).second, 30u);
    EXPECT_EQ(run(2).first, "consume failed");
    EXPECT_EQ(run(2).second, 40u);
    EXPECT_EQ(run(3).first, "");
    EXPECT_EQ(run(3).second, 100u);
  }
}

TEST(OrderedPool, ParallelForChunksCoversEveryIndexOnce) {
  for (int threads : {1, 2, 5}) {
    for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{63}, std::size_t{64}, std::size_t{1000}}) {
      std::vector<std::atomic<int>> hits(n);
      parallel_for_chunks(n, 64, threads, [&](std::size_t begin, std::size_t end) {
        EXPECT_LE(end - begin, 64u);
        for (std::size_t i = begin; i < end; ++i) ++hits[i];
      });
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(hits[i].load(), 1) << i;
    }
  }
}
