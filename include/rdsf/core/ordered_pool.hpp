#pragma once
// The library's one ordered thread pool: an ordered parallel map over items handed out one by one.
//   claim(item)     -> bool   fills the next item, false at the end. Called one call at a time, in order
//                             (never two at once; not under the pool's lock, so a claim that waits for a
//                             camera does not hold up the rest): keep it cheap (take an index or a path;
//                             reading a sequential file or a device here is fine, it is what they allow).
//   work(item)      -> result the heavy part, on `threads` threads at once, any item on any of them: the
//                             calling thread and threads - 1 workers (the calling thread works an item
//                             whenever the next result to consume is not ready, so `threads` threads keep
//                             `threads` cores busy, with no extra thread waking up to consume).
//   consume(result) -> bool   on the calling thread, results in claim order, one at a time; false stops.
// Invariants:
//   - consume sees exactly the sequence of `while (claim(item)) if (!consume(work(item))) break;`, so when
//     work is deterministic the outcome does not depend on the thread count (with threads == 1 that loop is
//     what runs, on the calling thread, no thread started);
//   - at most `ahead` items are claimed and not yet consumed (bounded memory; at least `threads`);
//   - errors too: an exception thrown by claim or work for item k stops further claims and is rethrown on
//     the calling thread after items 0 .. k-1 were consumed, as the loop would; one thrown by consume is
//     rethrown at once; an item beyond where consume returned false never throws (the loop never got there).
// The thread count is resolved by resolve_thread_count (0: one per core).
#include <algorithm>
#include <cstddef>
#include <functional>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "rdsf/core/thread_count.hpp"

namespace rdsf {

namespace detail {

/// The type-erased engine behind ordered_map: every callback gets the slot (sequence number % ahead) of
/// its item. threads >= 2, ahead >= threads.
void run_ordered_pool(int threads, std::size_t ahead, const std::function<bool(std::size_t)>& claim,
                      const std::function<void(std::size_t)>& work, const std::function<bool(std::size_t)>& consume);

}  // namespace detail

/// Items claimed ahead of the consumer for `threads` workers when the caller has no better idea.
inline std::size_t default_items_ahead(int threads) { return 2 * static_cast<std::size_t>(resolve_thread_count(threads)) + 2; }

/// The ordered parallel map described above. `Item` must be default-constructible and movable; the result
/// type is what work(Item&) returns (return a dummy value when there is nothing to hand on).
template <typename Item, typename Claim, typename Work, typename Consume>
void ordered_map(int threads, std::size_t ahead, Claim&& claim, Work&& work, Consume&& consume) {
  using Result = std::decay_t<std::invoke_result_t<Work&, Item&>>;
  threads = resolve_thread_count(threads);
  if (threads == 1) {
    while (true) {
      Item item;
      if (!claim(item)) return;
      if (!consume(work(item))) return;
    }
  }
  ahead = std::max<std::size_t>(ahead, static_cast<std::size_t>(threads));
  std::vector<std::optional<Item>> items(ahead);
  std::vector<std::optional<Result>> results(ahead);
  detail::run_ordered_pool(
      threads, ahead,
      [&](std::size_t slot) {
        Item item;
        if (!claim(item)) return false;
        items[slot].emplace(std::move(item));
        return true;
      },
      [&](std::size_t slot) {
        results[slot].emplace(work(*items[slot]));
        items[slot].reset();
      },
      [&](std::size_t slot) {
        Result result = std::move(*results[slot]);
        results[slot].reset();
        return static_cast<bool>(consume(std::move(result)));
      });
}

/// fn(begin, end) over [0, n) in chunks of `chunk` indices taken by `threads` workers as they come free
/// (for uneven work; every index handled by exactly one call). Built on ordered_map.
template <typename Fn>
void parallel_for_chunks(std::size_t n, std::size_t chunk, int threads, Fn&& fn) {
  chunk = std::max<std::size_t>(1, chunk);
  std::size_t next = 0;
  ordered_map<std::size_t>(
      threads, default_items_ahead(threads),
      [&](std::size_t& begin) {
        if (next >= n) return false;
        begin = next;
        next = std::min(n, next + chunk);
        return true;
      },
      [&](std::size_t& begin) {
        fn(begin, std::min(n, begin + chunk));
        return true;
      },
      [](bool) { return true; });
}

}  // namespace rdsf
