#include "rdsf/classifier/row_shards.hpp"

#include <algorithm>

#include "rdsf/core/error.hpp"

namespace rdsf {

void RowShards::sum(double*, std::size_t) const {}
std::pair<std::size_t, std::size_t> RowShards::sum_own_block(double*, std::size_t units, std::size_t) const {
  return {0, units};
}
void RowShards::max(double*, std::size_t) const {}
std::vector<double> RowShards::gather(const std::vector<double>& local) const { return local; }
std::vector<std::string> RowShards::gather_text(const std::string& local) const { return {local}; }

std::vector<double> gather_in_order(const RowShards& shards, const std::vector<double>& local,
                                    const std::vector<int>& owner) {
  if (!shards.distributed()) return local;
  const std::vector<double> all = shards.gather(local);
  std::vector<std::size_t> next(static_cast<std::size_t>(shards.size()) + 1, 0);
  for (int r : owner) ++next[static_cast<std::size_t>(r) + 1];
  for (std::size_t r = 1; r < next.size(); ++r) next[r] += next[r - 1];
  if (all.size() != owner.size() || next.back() != all.size()) {
    throw Error("data-parallel training: the ranks returned " + std::to_string(all.size()) + " values for " +
                std::to_string(owner.size()) + " entries");
  }
  std::vector<double> out(owner.size());
  for (std::size_t k = 0; k < owner.size(); ++k) out[k] = all[next[static_cast<std::size_t>(owner[k])]++];
  return out;
}

RowOwners::RowOwners(const RowShards* s, std::vector<int> owners) : shards(s), owner(std::move(owners)) {
  const int here = shards == nullptr ? 0 : shards->rank();
  local_of.assign(owner.size(), -1);
  long next = 0;
  for (std::size_t i = 0; i < owner.size(); ++i) {
    if (owner[i] == here) local_of[i] = next++;
  }
}

std::vector<int> RowOwners::owners_of(const std::vector<std::size_t>& index) const {
  std::vector<int> out;
  if (owner.empty()) return out;
  out.reserve(index.size());
  for (std::size_t i : index) out.push_back(owner[i]);
  return out;
}

RowOwners RowOwners::subset(const std::vector<int>& index) const {
  if (owner.empty()) return {};
  std::vector<int> owners;
  owners.reserve(index.size());
  for (int i : index) owners.push_back(owner[static_cast<std::size_t>(i)]);
  return RowOwners(shards, std::move(owners));
}

std::vector<double> RowOwners::whole(const std::vector<double>& local, const std::vector<std::size_t>& index) const {
  if (!distributed()) return local;
  return gather_in_order(*shards, local, owners_of(index));
}

}  // namespace rdsf
