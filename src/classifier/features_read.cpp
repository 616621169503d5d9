#include "classifier/features_read.hpp"

#include <algorithm>

namespace rdsf {

std::vector<int> features_read(const std::vector<WeakClassifier>& weak) {
  std::vector<int> out;
  for (const WeakClassifier& w : weak) out.push_back(w.feature);  // one per weak classifier (LUT, stump)
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace rdsf
