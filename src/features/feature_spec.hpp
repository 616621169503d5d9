#pragma once
// What an RDSF vector is, exactly: the window, the cells, the histogram bins and the order of the pairs.
// Its canonical text and stable hash go into every sample set and model file, so that a model is never
// applied to features computed another way.
//
// Default (the thesis's RDSF over a 64x128 window):
//   - 8x8-pixel cells: 8 across, 16 down, 128 cells, numbered row-major (cell = row * 8 + column);
//   - per cell a histogram of 26 bins, normalised to sum 1:
//       bin 0       "no reading or outside the layer" (depth 0 in the masked crop),
//       bins 1..25  depth in [0.3 m * (b-1), 0.3 m * b), i.e. 0.3 m bins up to 7.5 m as in the original
//                   RDSF paper (Ikemura and Fujiyoshi); depths of 7.5 m and beyond fall into bin 25;
//   - the Bhattacharyya coefficient sum_b sqrt(p_b q_b) of every pair of cells (i, j), i < j, in row-major
//     order of the pair: (0,1), (0,2), ..., (0,127), (1,2), ..., (126,127): 128 * 127 / 2 = 8128 values,
//     each in [0, 1].
#include <cstdint>
#include <string>

namespace rdsf {

struct FeatureSpec {
  int window_width_px = 64;
  int window_height_px = 128;
  int cell_px = 8;
  int bin_width_mm = 300;
  int max_depth_mm = 7500;

  int cells_x() const { return window_width_px / cell_px; }
  int cells_y() const { return window_height_px / cell_px; }
  int cell_count() const { return cells_x() * cells_y(); }
  /// Histogram bins per cell, the "no reading" bin included.
  int bin_count() const { return 1 + max_depth_mm / bin_width_mm; }
  /// Length of the feature vector: cell_count * (cell_count - 1) / 2.
  int dimension() const { return cell_count() * (cell_count() - 1) / 2; }
  /// Position of the pair (i, j), i < j, in the vector.
  int pair_index(int i, int j) const { return i * (2 * cell_count() - i - 1) / 2 + (j - i - 1); }
  /// The pair (i, j) at position `index`.
  void pair_at(int index, int& i, int& j) const;

  /// "rdsf/1 window=64x128 cell=8 bins=nodata+25x300mm clamp=7500mm pairs=upper-row-major crop=nearest-masked"
  std::string canonical() const;
  /// 16 hex digits of the stable hash of canonical().
  std::string hash() const;
  /// Throws Error when the numbers do not make a valid spec (cells must tile the window, etc.).
  void validate() const;
  bool operator==(const FeatureSpec& other) const { return canonical() == other.canonical(); }
  bool operator!=(const FeatureSpec& other) const { return !(*this == other); }
};

}  // namespace rdsf
