#pragma once
// What an RDSF vector is, exactly: the window, the regions, the histogram bins and the order of the pairs.
// Its canonical text and stable hash go into every sample set and model file, so that a model is never
// applied to features computed another way. Two layouts of regions are known (see docs/features.md):
//
// "rdsf" (layout Cells, the default: the thesis's RDSF over a 64x128 window):
//   - 8x8-pixel cells: 8 across, 16 down, 128 cells, numbered row-major (cell = row * 8 + column);
//   - per cell a histogram of 26 bins, normalised to sum 1:
//       bin 0       "no reading or outside the layer" (depth 0 in the masked crop),
//       bins 1..25  depth in [0.3 m * (b-1), 0.3 m * b), i.e. 0.3 m bins up to 7.5 m as in the original
//                   RDSF paper (Ikemura and Fujiyoshi); depths of 7.5 m and beyond fall into bin 25;
//   - the Bhattacharyya coefficient sum_b sqrt(p_b q_b) of every pair of cells (i, j), i < j, in row-major
//     order of the pair: (0,1), (0,2), ..., (0,127), (1,2), ..., (126,127): 128 * 127 / 2 = 8128 values,
//     each in [0, 1].
//
// "rdsf-rect" (layout Rects, after the RDSF paper: Ikemura and Fujiyoshi, "Real-time human detection using
// relational depth similarity features", ACCV 2010): the regions are squares of side rect_min_px,
// rect_min_px + rect_step_px, ..., rect_max_px at every top-left corner on a grid of rect_stride_px that
// keeps the square inside the window, numbered by side (smallest first), then row-major by top-left corner.
// Defaults: sides 8, 16, ..., 64 at an 8-px stride over 64x128: 128 + 105 + 84 + 65 + 48 + 33 + 20 + 9 = 492
// squares and 492 * 491 / 2 = 120,786 pairs (our reading of the paper's set-up). Bins, normalisation and
// pair order as above; a region's histogram comes from an integral histogram of the crop.
//
// In both, a region of area A with c_b pixels in bin b has p_b = float(c_b) / float(A), and the coefficient
// is computed as the sequential float sum over b ascending of sqrt(p_b) * sqrt(q_b), clamped to [0, 1]
// (bins where either is zero add exactly 0): every path (full vector, only the features a model reads)
// gives the same bits.
#include <cstdint>
#include <string>
#include <vector>

namespace rdsf {

/// A region of the window in pixels: columns [x, x + width), rows [y, y + height).
struct FeatureRegion {
  int x = 0, y = 0, width = 0, height = 0;
  int area() const { return width * height; }
};

struct FeatureSpec {
  enum class Layout { Cells, Rects };
  Layout layout = Layout::Cells;
  int window_width_px = 64;
  int window_height_px = 128;
  int cell_px = 8;          ///< Cells: side of the cells that tile the window
  int rect_min_px = 8;      ///< Rects: smallest square side
  int rect_max_px = 64;     ///< Rects: largest square side
  int rect_step_px = 8;     ///< Rects: sides grow by this
  int rect_stride_px = 8;   ///< Rects: top-left corners lie on this grid
  int bin_width_mm = 300;
  int max_depth_mm = 7500;

  /// The thesis's spec ("rdsf", the default-constructed one).
  static FeatureSpec thesis() { return FeatureSpec{}; }
  /// The paper's rectangles ("rdsf-rect" with its defaults).
  static FeatureSpec rect();
  /// Names this build knows, for help texts: {"rdsf", "rdsf-rect"}.
  static std::vector<std::string> known_names();
  /// A spec from a command-line text "NAME[:key=value,...]": NAME rdsf (keys cell, bin, clamp) or rdsf-rect
  /// (keys min, max, step, stride, bin, clamp; lengths in px, bin and clamp in mm). Throws Error naming an
  /// unknown name, key or value, or an invalid spec.
  static FeatureSpec parse(const std::string& text);
  /// The spec whose canonical() is `text`; throws Error when no spec this build knows has that text.
  static FeatureSpec from_canonical(const std::string& text);

  /// "rdsf" or "rdsf-rect".
  std::string name() const { return layout == Layout::Cells ? "rdsf" : "rdsf-rect"; }
  /// The text parse() reads back: the name alone for the defaults, else "NAME:key=value,...".
  std::string option_text() const;

  int cells_x() const { return window_width_px / cell_px; }
  int cells_y() const { return window_height_px / cell_px; }
  /// Cells layout: number of cells (the regions); Rects: number of regions too.
  int cell_count() const { return region_count(); }
  /// Number of regions whose histograms are compared.
  int region_count() const;
  /// Region `r` (0 <= r < region_count()) in the order of the pairs.
  FeatureRegion region(int r) const;
  std::vector<FeatureRegion> regions() const;
  /// Histogram bins per region, the "no reading" bin included.
  int bin_count() const { return 1 + max_depth_mm / bin_width_mm; }
  /// Length of the feature vector: region_count * (region_count - 1) / 2.
  int dimension() const {
    const long long n = region_count();
    return static_cast<int>(n * (n - 1) / 2);
  }
  /// Position of the pair (i, j), i < j, in the vector.
  int pair_index(int i, int j) const {
    const long long n = region_count();
    return static_cast<int>(i * (2 * n - i - 1) / 2 + (j - i - 1));
  }
  /// The pair (i, j) at position `index`.
  void pair_at(int index, int& i, int& j) const;
  /// "cells 3-17" or "rects 8x8@0,0-16x16@8,24": the regions of a feature, for people.
  std::string describe_feature(int index) const;

  /// "rdsf/1 window=64x128 cell=8 bins=nodata+25x300mm clamp=7500mm pairs=upper-row-major crop=nearest-masked"
  std::string canonical() const;
  /// 16 hex digits of the stable hash of canonical().
  std::string hash() const;
  /// Throws Error when the numbers do not make a valid spec (cells must tile the window, etc.).
  void validate() const;
  bool operator==(const FeatureSpec& other) const { return canonical() == other.canonical(); }
  bool operator!=(const FeatureSpec& other) const { return !(*this == other); }
};

/// Largest number a feature spec text may give (window, cell, rectangle or depth); keeps products in int.
constexpr int kMaxFeatureSpecNumber = 1 << 15;
/// Largest dimension a spec may have (so that feature indices and row lengths stay within int).
constexpr long long kMaxFeatureDimension = 1LL << 30;

}  // namespace rdsf
