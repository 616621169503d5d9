#include "rdsf/segmentation/local_background.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "rdsf/core/error.hpp"

namespace rdsf {
namespace {

// Range maxima of one grid row: level k holds the maximum of 2^k samples from each position.
class RowMaxima {
 public:
  void build(const std::vector<std::uint16_t>& row) {
    const int n = static_cast<int>(row.size());
    levels_ = 1;
    while ((1 << levels_) <= n) ++levels_;
    table_.assign(static_cast<std::size_t>(levels_) * n, 0);
    std::copy(row.begin(), row.end(), table_.begin());
    for (int k = 1; k < levels_; ++k) {
      const std::uint16_t* below = &table_[static_cast<std::size_t>(k - 1) * n];
      std::uint16_t* level = &table_[static_cast<std::size_t>(k) * n];
      const int half = 1 << (k - 1);
      for (int i = 0; i + (1 << k) <= n; ++i) level[i] = std::max(below[i], below[i + half]);
    }
    n_ = n;
  }
  // The maximum of samples first..last (first <= last, both within the row).
  std::uint16_t max(int first, int last) const {
    const int k = 31 - __builtin_clz(static_cast<unsigned>(last - first + 1));  // the largest 2^k <= the length
    const std::uint16_t* level = &table_[static_cast<std::size_t>(k) * n_];
    return std::max(level[first], level[last - (1 << k) + 1]);
  }

 private:
  std::vector<std::uint16_t> table_;
  int levels_ = 0, n_ = 0;
};

// w(d) = max(1, round(reach_px_mm / d)) grid columns for every depth d > 0, as a table: one division and
// rounding per depth value once per reach (this thread's, rebuilt when the reach changes), not per cell.
const std::vector<std::uint16_t>& reach_cells(double reach_px_mm) {
  thread_local std::vector<std::uint16_t> table;
  thread_local double made_for = -1.0;
  if (made_for != reach_px_mm) {
    table.assign(65536, 1);
    for (int d = 1; d < 65536; ++d) {
      const long w = std::max(1L, std::lround(reach_px_mm / d));
      table[static_cast<std::size_t>(d)] = static_cast<std::uint16_t>(std::min(w, 65535L));
    }
    made_for = reach_px_mm;
  }
  return table;
}

}  // namespace

void local_background(const cv::Mat1w& depth_mm, const CameraModel& camera, double reach_mm, cv::Mat1w& far) {
  if (!(reach_mm > 0)) throw Error("local background: the reach must be positive");
  if (!(camera.fx_px > 0)) throw Error("local background: the camera's fx must be positive");
  constexpr int g = kLocalBackgroundGridPx;
  const int cols = depth_mm.cols, rows = depth_mm.rows;
  const int grid_cols = (cols + g - 1) / g, grid_rows = (rows + g - 1) / g;
  // w in grid columns for depth d: round(fx * R / d / g) = round(reach_px_mm / d).
  const double reach_px_mm = camera.fx_px * reach_mm / g;
  far.create(depth_mm.size());  // kept when it has the size already: no new pages to fault in a frame
  const std::vector<std::uint16_t>& w_of = reach_cells(reach_px_mm);
  std::vector<std::uint16_t> cells(static_cast<std::size_t>(grid_cols)), behind(static_cast<std::size_t>(grid_cols));
  std::vector<std::uint16_t> expanded(static_cast<std::size_t>(grid_cols) * g), column_max(static_cast<std::size_t>(cols));
  RowMaxima maxima;
  for (int gr = 0; gr < grid_rows; ++gr) {
    const int first_row = gr * g, end_row = std::min(rows, first_row + g);
    // Each cell's farthest reading: the maximum over the band's rows per column (a loop the compiler
    // vectorises), then over each cell's g columns.
    std::copy_n(depth_mm.ptr<std::uint16_t>(first_row), cols, column_max.begin());
    for (int r = first_row + 1; r < end_row; ++r) {
      const std::uint16_t* d = depth_mm.ptr<std::uint16_t>(r);
      std::uint16_t* m = column_max.data();
      for (int c = 0; c < cols; ++c) m[c] = std::max(m[c], d[c]);
    }
    for (int j = 0; j < grid_cols; ++j) {
      const int first = j * g, end = std::min(cols, first + g);
      std::uint16_t m = column_max[static_cast<std::size_t>(first)];
      for (int c = first + 1; c < end; ++c) m = std::max(m, column_max[static_cast<std::size_t>(c)]);
      cells[static_cast<std::size_t>(j)] = m;
    }
    maxima.build(cells);
    for (int j = 0; j < grid_cols; ++j) {
      const std::uint16_t d = cells[j];
      behind[j] = 1;
      if (d == 0 || j == 0 || j == grid_cols - 1) continue;  // no reading, or a side without a cell
      const int w = w_of[d];
      const std::uint16_t b =
          std::min(maxima.max(std::max(0, j - w), j - 1), maxima.max(j + 1, std::min(grid_cols - 1, j + w)));
      if (b > 0) behind[j] = b;
    }
    for (int j = 0; j < grid_cols; ++j) std::fill_n(&expanded[static_cast<std::size_t>(j) * g], g, behind[j]);
    for (int r = first_row; r < end_row; ++r) std::copy_n(expanded.begin(), cols, far.ptr<std::uint16_t>(r));
  }
}

cv::Mat1w local_background(const cv::Mat1w& depth_mm, const CameraModel& camera, double reach_mm) {
  cv::Mat1w far;
  local_background(depth_mm, camera, reach_mm, far);
  return far;
}

}  // namespace rdsf
