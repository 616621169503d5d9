#include "rdsf/candidates/duplicate_candidates.hpp"

#include <algorithm>
#include <numeric>

#include "rdsf/core/error.hpp"

namespace rdsf {

std::vector<char> duplicate_candidates(const std::vector<CandidateKin>& kin, const std::vector<double>& scores) {
  if (kin.size() != scores.size()) {
    fail("duplicate_candidates", std::to_string(kin.size()) + " candidates but " + std::to_string(scores.size()) + " scores");
  }
  std::vector<char> duplicate(kin.size(), 0);
  std::vector<std::size_t> order(kin.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return scores[a] > scores[b]; });
  std::vector<std::size_t> kept;
  for (std::size_t i : order) {
    const CandidateKin& k = kin[i];
    const bool suppressed = k.object >= 0 && std::any_of(kept.begin(), kept.end(), [&](std::size_t j) {
                              return kin[j].object == k.object && kin[j].part != k.part;
                            });
    if (suppressed) {
      duplicate[i] = 1;
    } else {
      kept.push_back(i);
    }
  }
  return duplicate;
}

}  // namespace rdsf
