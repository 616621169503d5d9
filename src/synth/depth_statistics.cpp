#include "rdsf/synth/depth_statistics.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace rdsf::synth {

DepthStatistics depth_statistics(const cv::Mat1w& depth_mm, int edge_jump_mm, int edge_max_gap_px) {
  DepthStatistics s;
  if (depth_mm.empty()) return s;
  std::vector<int> histogram(65536, 0);
  long long valid = 0, holed_edges = 0, hole_runs = 0, single_pixel_holes = 0;
  for (int y = 0; y < depth_mm.rows; ++y) {
    const std::uint16_t* row = depth_mm.ptr<std::uint16_t>(y);
    int previous_x = -1;
    int previous_mm = 0;
    for (int x = 0; x < depth_mm.cols; ++x) {
      const int d = row[x];
      ++histogram[static_cast<std::size_t>(d)];
      if (d == 0) {
        const bool starts = x == 0 || row[x - 1] != 0;
        hole_runs += starts ? 1 : 0;
        single_pixel_holes += starts && (x + 1 == depth_mm.cols || row[x + 1] != 0) ? 1 : 0;
        continue;
      }
      ++valid;
      if (previous_x >= 0 && x - previous_x <= edge_max_gap_px) {
        const int jump = std::abs(d - previous_mm);
        if (jump > edge_jump_mm && jump * 10 > std::max(d, previous_mm)) {
          ++s.edges;
          if (x - previous_x > 1) ++holed_edges;
        }
      }
      previous_x = x;
      previous_mm = d;
    }
  }
  const long long total = static_cast<long long>(depth_mm.total());
  s.valid_fraction = static_cast<double>(valid) / static_cast<double>(total);
  s.edge_hole_fraction = s.edges > 0 ? static_cast<double>(holed_edges) / static_cast<double>(s.edges) : 0.0;
  s.hole_runs_per_row = static_cast<double>(hole_runs) / static_cast<double>(depth_mm.rows);
  s.single_pixel_hole_share =
      hole_runs > 0 ? static_cast<double>(single_pixel_holes) / static_cast<double>(hole_runs) : 0.0;
  if (valid > 0) {
    auto percentile = [&](double q) {
      const long long rank = static_cast<long long>(q * static_cast<double>(valid - 1));
      long long seen = 0;
      for (int d = 1; d < 65536; ++d) {
        seen += histogram[static_cast<std::size_t>(d)];
        if (seen > rank) return static_cast<double>(d);
      }
      return 65535.0;
    };
    s.p5_mm = percentile(0.05);
    s.p50_mm = percentile(0.50);
    s.p95_mm = percentile(0.95);
  }
  return s;
}

}  // namespace rdsf::synth
