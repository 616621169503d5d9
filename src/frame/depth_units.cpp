#include "rdsf/frame/depth_units.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace rdsf {

int median_reading_mm(const cv::Mat1w& depth_mm) {
  std::vector<std::uint16_t> readings;
  readings.reserve(depth_mm.total());
  for (int y = 0; y < depth_mm.rows; ++y) {
    const std::uint16_t* row = depth_mm.ptr<std::uint16_t>(y);
    for (int x = 0; x < depth_mm.cols; ++x)
      if (row[x] != 0) readings.push_back(row[x]);
  }
  if (readings.empty()) return 0;
  const auto middle = readings.begin() + static_cast<std::ptrdiff_t>(readings.size() / 2);
  std::nth_element(readings.begin(), middle, readings.end());
  return *middle;
}

std::string depth_units_note(const cv::Mat1w& depth_mm) {
  const int median_mm = median_reading_mm(depth_mm);
  if (median_mm == 0 || plausible_median_reading_mm(median_mm)) return {};
  const bool far = median_mm > kMaxMedianReadingMm;
  return "the median reading is " + std::to_string(median_mm) + " mm, " + (far ? "beyond" : "below") +
         " a Kinect-class camera's range: if the depth is not in millimetres, state its unit in a camera.yml "
         "beside the frames (" +
         (far ? "depth_unit_mm: 0.2 for 5000 units a metre, as TUM RGB-D; 0.1 for 0.1 mm units"
              : "depth_unit_mm: 10 for centimetres") +
         ")";
}

}  // namespace rdsf
