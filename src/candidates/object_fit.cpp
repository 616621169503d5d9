#include "rdsf/candidates/object_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "rdsf/candidates/band_gather.hpp"

namespace rdsf {
namespace {

// The band's columns at steps gathered..until-1 (of n) from `start` in `direction`, gathered left to right
// in memory and stored by step into band.
void gather_steps(const LayerView& layer, std::vector<BandColumn>& band, int direction, int start, int n,
                  int& gathered, int until, int row_lo, int row_hi) {
  const int from_step = gathered, to_step = std::min(until, n);
  if (to_step <= from_step) return;
  const int c0 = direction < 0 ? start - (to_step - 1) : start + from_step;  // leftmost column
  const int count = to_step - from_step;
  BandColumn columns[kBandChunk + 1];
  gather_band(*layer.labels, *layer.depth_mm, layer.label, c0, count, row_lo, row_hi, columns);
  for (int j = 0; j < count; ++j) {
    const int step = direction < 0 ? to_step - 1 - j : from_step + j;
    band[static_cast<std::size_t>(step)] = columns[j];
  }
  gathered = to_step;
}

}  // namespace

bool nearer_in_band(const LayerView& layer, int c, int row_lo, int row_hi, int needed) {
  int nearer = 0;
  for (int y = row_lo; y <= row_hi && nearer < needed; y += 2) {
    const int label = layer.labels->ptr<std::uint8_t>(y)[c];
    nearer += label > 0 && label < layer.label;
  }
  return nearer >= needed;
}

void fit_object(const LayerShape& shape, LayerObject& o, int lo, int hi) {
  const LayerView& layer = shape.layer();
  const FitParams& fit = shape.params().fit;
  const int column_gap = shape.params().column_gap;
  o.fit_first = o.first;
  o.fit_last = o.last;
  o.fit_top = o.top;
  const int reach = shape.columns_px(fit.reach_cm);
  if (reach <= 0) return;
  const int row_lo = std::max(0, o.top - reach);
  const int row_hi = std::min(layer.labels->rows - 1, o.top + 3 * (o.bottom - o.top) / 4);
  thread_local std::vector<BandColumn> band;  // reused: fitted for every object of every layer
  for (int direction : {-1, 1}) {
    const int start = direction < 0 ? o.first : o.last;
    // Columns start+direction ... as far as reach and lo..hi allow, stopping at a passing column.
    int far = start;
    for (int c = start + direction; c >= lo && c <= hi && std::abs(c - start) <= reach && !shape.passes(c); c += direction) far = c;
    if (far == start) continue;
    // The band's pixels per column, gathered kBandChunk columns at a time from the object's edge column
    // (start) outwards, only as far as the walk below goes (it stops after column_gap columns that do
    // not continue the object); the same counts as gathering start..far at once.
    const int n = std::abs(far - start) + 1;  // columns start, start + direction, ..., far
    band.assign(static_cast<std::size_t>(n), BandColumn{});
    int gathered = 0;
    const auto gather = [&](int until) { gather_steps(layer, band, direction, start, n, gathered, until, row_lo, row_hi); };
    auto mean_depth = [&](int step) {
      const BandColumn& b = band[static_cast<std::size_t>(step)];
      return b.count > 0 ? static_cast<double>(b.depth_sum) / b.count : 0.0;
    };
    // First the columns a walk that takes none needs (most objects have nothing attached), then kBandChunk more.
    gather(1 + std::min(kBandChunk, std::max(1, column_gap + 1)));
    // A piece continues the object: its mean depth is within fit.depth_step_mm of the last column taken.
    double previous_depth = mean_depth(0);
    int edge = start, gap = 0, occluded = 0, top = o.fit_top;
    int previous_count = band[0].count;
    const int occlusion_gap = shape.columns_px(fit.occlusion_gap_cm);
    for (int step = 1; step < n; ++step) {
      if (step >= gathered) gather(step + kBandChunk);
      const int c = start + direction * step;
      const BandColumn& b = band[static_cast<std::size_t>(step)];
      const bool continues = b.count >= 2 && (previous_depth <= 0 || fit.depth_step_mm <= 0 ||
                                              std::abs(mean_depth(step) - previous_depth) <= fit.depth_step_mm);
      if (continues) {
        edge = c;
        gap = 0;
        occluded = 0;
        top = std::min(top, b.first_row);
        previous_depth = mean_depth(step);
        previous_count = b.count;
      } else if (occluded < occlusion_gap && nearer_in_band(layer, c, row_lo, row_hi, std::max(2, previous_count / 2))) {
        ++occluded;
      } else if (++gap > column_gap) {
        break;
      }
    }
    (direction < 0 ? o.fit_first : o.fit_last) = edge;
    o.fit_top = top;
  }
}

}  // namespace rdsf
