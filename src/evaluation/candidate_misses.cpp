#include "rdsf/evaluation/candidate_misses.hpp"

#include "rdsf/core/error.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

namespace rdsf {

MissShape miss_shape(const cv::Rect& person, const cv::Rect& best, double best_iou) {
  if (best_iou >= 0.5) fail("miss_shape", "IoU >= 0.5 is a match, not a miss");
  if (best_iou < 0.1 || person.width <= 0 || person.height <= 0) return MissShape::none;
  const double width = static_cast<double>(best.width) / person.width;
  const double height = static_cast<double>(best.height) / person.height;
  if (width > 1.4) return MissShape::wide;
  if (width < 0.7) return MissShape::narrow;
  if (height > 1.3) return MissShape::tall;
  if (height < 0.75) return MissShape::short_box;
  return MissShape::shifted;
}

const char* miss_shape_name(MissShape shape) {
  switch (shape) {
    case MissShape::none: return "none";
    case MissShape::wide: return "wide";
    case MissShape::narrow: return "narrow";
    case MissShape::tall: return "tall";
    case MissShape::short_box: return "short";
    case MissShape::shifted: return "shifted";
  }
  return "?";
}

std::int64_t MissShapes::total() const { return std::accumulate(count.begin(), count.end(), std::int64_t{0}); }

std::string MissShapes::summary() const {
  std::vector<int> order(kMissShapes);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return count[a] > count[b]; });
  std::string text;
  for (const int s : order) {
    if (count[static_cast<std::size_t>(s)] == 0) break;
    if (!text.empty()) text += ", ";
    text += std::to_string(count[static_cast<std::size_t>(s)]) + " " + miss_shape_name(static_cast<MissShape>(s));
  }
  return text;
}

}  // namespace rdsf
