#include "rdsf/segmentation/depth_candidates.hpp"

#include <algorithm>
#include <cstdlib>

namespace rdsf {

std::vector<int> scan_depth_candidates(const cv::Mat1w& depth_mm, const SegmentationParams& p) {
  std::vector<int> candidates;
  const int width = depth_mm.cols;
  const int step = std::max(1, p.row_step);
  for (int row = 0; row < depth_mm.rows; row += step) {
    const std::uint16_t* d = depth_mm.ptr<std::uint16_t>(row);
    for (int j = p.left_border_jump ? 0 : 1; j + p.n < width; ++j) {
      const int value = d[j];
      // The left image border counts as a jump: an object cut by it is seeded like one entered from the
      // right (a right-border object is seeded by its own left edge).
      if (j > 0 && std::abs(value - static_cast<int>(d[j - 1])) <= p.depth_threshold_mm) continue;
      bool holds = true;
      for (int m = 1; m <= p.n && holds; ++m) holds = std::abs(static_cast<int>(d[j + m]) - value) <= p.range_threshold_mm;
      if (holds) candidates.push_back(value);
    }
  }
  return candidates;
}

std::vector<double> merge_depth_candidates(std::vector<int> raw, const SegmentationParams& p) {
  std::sort(raw.begin(), raw.end());
  std::vector<double> merged;
  auto it = raw.begin();
  if (it != raw.end() && *it == 0) {
    merged.push_back(0.0);  // every "no reading" candidate is one
    it = std::upper_bound(raw.begin(), raw.end(), 0);
  }
  while (it != raw.end()) {
    const int run_start = *it;
    double sum = 0;
    int count = 0;
    while (it != raw.end() && *it - run_start <= p.candidate_threshold_mm) {
      sum += *it;
      ++count;
      ++it;
    }
    merged.push_back(sum / count);
  }
  return merged;
}

}  // namespace rdsf
