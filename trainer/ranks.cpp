#include "trainer/ranks.hpp"

#include <iostream>
#include <sstream>
#include <vector>

namespace rdsf {

void on_every_rank(const RowShards& shards, const std::string& what, const std::function<void()>& step) {
  if (!shards.distributed()) return step();
  std::string message;
  try {
    step();
  } catch (const std::exception& e) {
    message = e.what();
    if (message.empty()) message = "failed";
  }
  const std::vector<std::string> all = shards.gather_text(message);
  for (std::size_t r = 0; r < all.size(); ++r) {
    if (all[r].empty()) continue;
    if (shards.rank() != 0) throw QuietExit{1};
    throw AgreedError("rank " + std::to_string(r) + " of " + std::to_string(shards.size()) + ": " + what + ": " + all[r]);
  }
}

void check_ranks_agree(const RowShards& shards, const std::string& what, const std::string& text) {
  if (!shards.distributed()) return;
  const std::vector<std::string> all = shards.gather_text(text);
  for (std::size_t r = 1; r < all.size(); ++r) {
    if (all[r] == all[0]) continue;
    if (shards.rank() != 0) throw QuietExit{1};
    std::istringstream mine(all[0]), theirs(all[r]);
    std::string a, b;
    while (true) {
      const bool more_a = static_cast<bool>(std::getline(mine, a)), more_b = static_cast<bool>(std::getline(theirs, b));
      if (!more_a) a = "(nothing)";
      if (!more_b) b = "(nothing)";
      if (a != b || (!more_a && !more_b)) break;
    }
    throw AgreedError("rank " + std::to_string(r) + " of " + std::to_string(shards.size()) + " has other " + what +
                " than rank 0: '" + b + "' where rank 0 has '" + a + "'");
  }
}

QuietCerr::QuietCerr(bool quiet) {
  if (quiet) saved_ = std::cerr.rdbuf(&null_);
}

QuietCerr::~QuietCerr() {
  if (saved_ != nullptr) std::cerr.rdbuf(saved_);
}

}  // namespace rdsf
