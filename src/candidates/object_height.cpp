#include "rdsf/candidates/object_height.hpp"

#include <algorithm>
#include <cstdint>

namespace rdsf {

double object_depth_mm(const cv::Mat1w& depth_crop) {
  std::vector<std::uint16_t> readings;
  readings.reserve(depth_crop.total());
  for (int r = 0; r < depth_crop.rows; ++r) {
    const std::uint16_t* row = depth_crop[r];
    for (int c = 0; c < depth_crop.cols; ++c) {
      if (row[c] != 0) readings.push_back(row[c]);
    }
  }
  if (readings.empty()) return 0.0;
  const auto middle = readings.begin() + static_cast<std::ptrdiff_t>(readings.size() / 2);
  std::nth_element(readings.begin(), middle, readings.end());
  return *middle;
}

double object_height_cm(const Candidate& candidate, const CameraModel& camera) {
  return camera.height_cm(candidate.strict_box.height, object_depth_mm(candidate.depth_crop));
}

bool taller_than_a_person(const Candidate& candidate, const CameraModel& camera, double max_height_cm) {
  if (max_height_cm <= 0 || candidate.depth_crop.empty()) return false;
  // The median is at most the farthest reading: an object not too tall even there needs no median (most
  // candidates; the median's partial sort costs about as much as the rest of a candidate's shaping).
  double farthest_mm = 0;
  cv::minMaxLoc(candidate.depth_crop, nullptr, &farthest_mm);
  if (camera.height_cm(candidate.strict_box.height, farthest_mm) <= max_height_cm) return false;
  return object_height_cm(candidate, camera) > max_height_cm;
}

}  // namespace rdsf
