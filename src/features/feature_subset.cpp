#include "rdsf/features/feature_subset.hpp"

#include <algorithm>

#include "rdsf/core/error.hpp"

namespace rdsf {

FeatureSubset::FeatureSubset(const FeatureSpec& spec, const std::vector<int>& features)
    : builder_(spec), features_(features) {
  std::sort(features_.begin(), features_.end());
  features_.erase(std::unique(features_.begin(), features_.end()), features_.end());
  const int dimension = spec.dimension();
  if (!features_.empty() && (features_.front() < 0 || features_.back() >= dimension)) {
    throw Error("feature subset: feature " + std::to_string(features_.front() < 0 ? features_.front() : features_.back()) +
                " is outside the " + std::to_string(dimension) + " features of " + spec.name());
  }
  std::vector<std::pair<int, int>> pairs;
  for (const int f : features_) {
    int i = 0, j = 0;
    spec.pair_at(f, i, j);
    pairs.emplace_back(i, j);
    regions_.push_back(i);
    regions_.push_back(j);
  }
  std::sort(regions_.begin(), regions_.end());
  regions_.erase(std::unique(regions_.begin(), regions_.end()), regions_.end());
  auto slot = [&](int region) {
    return static_cast<int>(std::lower_bound(regions_.begin(), regions_.end(), region) - regions_.begin());
  };
  for (const auto& [i, j] : pairs) slots_.emplace_back(slot(i), slot(j));
}

int FeatureSubset::position(int feature) const {
  const auto it = std::lower_bound(features_.begin(), features_.end(), feature);
  return it != features_.end() && *it == feature ? static_cast<int>(it - features_.begin()) : -1;
}

void FeatureSubset::compute(const cv::Mat1w& crop, float* out) const {
  thread_local RootHistograms h;
  builder_.compute(crop, regions_, h);
  if (h.bins < 4) {
    for (const auto& [i, j] : slots_) *out++ = pair_value(h, i, j);
    return;
  }
  for (const auto& [i, j] : slots_) {  // nearly every region has at most 4 bins: a branch well predicted
    *out++ = h.nz_count[static_cast<std::size_t>(j)] <= 4 ? pair_value_short(h, i, j) : pair_value(h, i, j);
  }
}

}  // namespace rdsf
