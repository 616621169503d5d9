#pragma once
// The one rule for a thread count given by a user (--threads N, a params struct's `threads`):
//   requested > 0  -> requested
//   requested <= 0 -> one per core (std::thread::hardware_concurrency(), at least 1)
// Every parallel part of the library resolves its count here, so "0" means the same everywhere.

namespace rdsf {

/// Number of threads to use for `requested` (see above). Always >= 1.
int resolve_thread_count(int requested);

}  // namespace rdsf
