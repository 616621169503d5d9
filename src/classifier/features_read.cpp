#include "rdsf/classifier/features_read.hpp"

#include <algorithm>

namespace rdsf {

std::vector<int> features_read(const std::vector<WeakClassifier>& weak) {
  std::vector<int> out;
  for (const WeakClassifier& w : weak) {
    for (const int f : w.features_read()) out.push_back(f);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void renumber_features(std::vector<WeakClassifier>& weak, const std::function<int(int)>& map) {
  for (WeakClassifier& w : weak) {
    w.feature = map(w.feature);
    for (LutNode& node : w.nodes) node.feature = map(node.feature);
  }
}

}  // namespace rdsf
