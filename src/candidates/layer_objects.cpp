#include "rdsf/candidates/layer_objects.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace rdsf {
namespace {

class ObjectShaper {
 public:
  ObjectShaper(const LayerView& layer, const CandidateParams& params)
      : layer_(layer), params_(params), runs_(*layer.runs), width_(static_cast<int>(layer.runs->size())) {
    const double min_height_cm = params.threshold_height_cm(layer.depth_mm_mean);
    passing_.resize(static_cast<std::size_t>(width_));
    int longest = 0;
    for (int c = 0; c < width_; ++c) longest = std::max(longest, run(c).length());
    // At depth d > 0 (and fy > 0) height_cm(length, d) grows with the length (each step of the formula
    // does), so "at least min_height_cm" is "length >= the shortest length that passes": found once by
    // bisection on the same formula over 0..longest (longest + 1 when none passes). Else (-1) every
    // column is measured.
    const auto shortest_passing = [&](double depth) {
      if (!(depth > 0) || !(layer.camera->fy_px > 0)) return -1;
      int lo = 0, hi = longest + 1;  // lengths below lo fail, lengths from hi on pass (or are none)
      while (lo < hi) {
        const int mid = lo + (hi - lo) / 2;
        if (layer.camera->height_cm(mid, depth) >= min_height_cm) {
          hi = mid;
        } else {
          lo = mid + 1;
        }
      }
      return lo;
    };
    const int shortest_at_mean = shortest_passing(layer.depth_mm_mean);
    const int shortest_at_max = shortest_passing(layer.depth_mm_max);
    const auto passes_at = [&](int length, double depth, int shortest) {
      return shortest >= 0 ? length >= shortest : layer.camera->height_cm(length, depth) >= min_height_cm;
    };
    for (int c = 0; c < width_; ++c) {
      const int length = run(c).length();
      bool passes = passes_at(length, layer.depth_mm_mean, shortest_at_mean);
      // A column that fails at the layer's mean depth may pass at its own (a layer spans up to
      // candidate_threshold of depth): measured where it could, at the median depth of its run.
      if (!passes && params.height_at_column_depth && length > 0 &&
          layer.depth_mm_mean < params.column_depth_layers_below_mm &&
          passes_at(length, layer.depth_mm_max, shortest_at_max)) {
        passes = layer.camera->height_cm(length, column_depth_mm(c, 4)) >= min_height_cm;
      }
      passing_[static_cast<std::size_t>(c)] = passes;
    }
  }

  const std::vector<char>& passing() const { return passing_; }

  std::vector<LayerObject> objects() const {
    // The thesis: passing columns joined across gaps of at most column_gap columns.
    std::vector<LayerObject> found;
    int c = 0;
    while (c < width_) {
      if (!passes(c)) {
        ++c;
        continue;
      }
      int last = c;
      for (int next = c + 1; next < width_ && next - last - 1 <= params_.column_gap; ++next) {
        if (passes(next)) last = next;
      }
      found.push_back(span(c, last));
      c = last + 1;
    }
    for (LayerObject& o : found) fit(o, 0, width_ - 1);
    if (params_.join_pieces) found = join(found);
    std::vector<LayerObject> kept;
    int object = 0;
    for (LayerObject& o : found) {
      if (!wide_enough(o) && !narrow_person(o)) continue;
      if (params_.max_object_width_cm > 0 && cm(o.last - o.first + 1) > params_.max_object_width_cm) continue;
      const bool at_border = o.fit_first == 0 || o.fit_last == width_ - 1;  // a person cut by it looks narrow
      if (!at_border && cm(o.fit_last - o.fit_first + 1) < params_.min_fitted_width_cm) continue;
      std::vector<LayerObject> pieces;
      bool by_heads = false;
      o.object = object++;
      if (split_wide_enabled() || split_heads_enabled()) split(o, pieces, 0, &by_heads);
      if (pieces.empty() || (by_heads ? params_.split_head_keep_whole : params_.split_keep_whole)) kept.push_back(o);
      kept.insert(kept.end(), pieces.begin(), pieces.end());
    }
    return kept;
  }

 private:
  const ColumnRun& run(int c) const { return runs_[static_cast<std::size_t>(c)]; }
  bool passes(int c) const { return passing_[static_cast<std::size_t>(c)] != 0; }
  double cm(int pixels) const { return layer_.camera->width_cm(pixels, layer_.depth_mm_mean); }
  int px(double centimetres) const {
    return static_cast<int>(centimetres * 10.0 * layer_.camera->fx_px / std::max(1.0, layer_.depth_mm_mean));
  }
  // Real width of the passing columns of o.first..o.last alone (the gaps between them left out).
  double passing_cm(const LayerObject& o) const {
    int n = 0;
    for (int x = o.first; x <= o.last; ++x) n += passes(x);
    return cm(n);
  }
  bool wide_enough(const LayerObject& o) const { return cm(o.last - o.first + 1) >= params_.min_width_cm; }
  // Step 4 (narrow_fitted_width_cm): an object too narrow over its passing columns that has a person's
  // fitted width, height, depth and a background above its top.
  bool narrow_person(const LayerObject& o) const {
    if (params_.narrow_fitted_width_cm <= 0) return false;
    if (cm(o.fit_last - o.fit_first + 1) < params_.narrow_fitted_width_cm) return false;
    if (cm(o.last - o.first + 1) < params_.narrow_passing_width_cm) return false;
    if (layer_.depth_mm_mean >= params_.narrow_layers_below_mm) return false;
    if (layer_.camera->height_cm(o.bottom - o.fit_top + 1, layer_.depth_mm_mean) < params_.narrow_min_height_cm) return false;
    return clear_above(o);
  }

  // Over the passing columns, at least half the pixels of the narrow_clear_above_cm band above the
  // object's top belong to other layers (rows above the image count as missing).
  bool clear_above(const LayerObject& o) const {
    const int band = std::max(1, px(params_.narrow_clear_above_cm));
    int other = 0, total = 0;
    for (int y = o.top - band; y < o.top; ++y) {
      const std::uint8_t* label = y >= 0 ? layer_.labels->ptr<std::uint8_t>(y) : nullptr;
      for (int x = o.first; x <= o.last; ++x, ++total) {
        if (label != nullptr && label[x] != 0 && label[x] != layer_.label) ++other;
      }
    }
    return total > 0 && 2 * other >= total;
  }

  bool split_wide_enabled() const {
    return params_.split_valley_cm > 0 || params_.split_depth_jump_mm > 0 || params_.split_step_cm > 0;
  }
  bool split_heads_enabled() const {
    return params_.split_head_drop_cm > 0 && layer_.depth_mm_mean < params_.split_head_layers_below_mm;
  }

  // The object over the passing columns of first..last (first and last pass).
  LayerObject span(int first, int last) const {
    LayerObject o;
    o.first = first;
    o.last = last;
    o.top = std::numeric_limits<int>::max();
    o.bottom = -1;
    for (int x = first; x <= last; ++x) {
      if (!passes(x)) continue;
      o.top = std::min(o.top, run(x).top);
      o.bottom = std::max(o.bottom, run(x).bottom);
      o.tallest = std::max(o.tallest, run(x).length());
    }
    std::vector<int> at_top;
    for (int x = first; x <= last; ++x) {
      if (passes(x) && run(x).top == o.top) at_top.push_back(x);
    }
    o.highest = at_top[at_top.size() / 2];
    o.fit_first = first;
    o.fit_last = last;
    o.fit_top = o.top;
    return o;
  }

  // Step 1: the fitted extent reaches over the columns beside the object that hold its pieces (an arm, a
  // hand: at least two of the layer's pixels, every other row, in the object's rows above its lowest
  // quarter, where the floor would be, or up to fit_reach_cm above its top), gaps of column_gap allowed,
  // up to fit_reach_cm each side, never into a passing column (that belongs to an object) nor beyond
  // lo..hi. The fitted top rises to the highest such pixel. A column that does not continue the object
  // but shows something nearer before the band (at least half as many pixels of nearer layers, in the
  // band's rows, as the column last taken has of the layer, and at least two) does not count towards
  // the gap for up to fit_occlusion_gap_cm of such columns after the column last taken.
  void fit(LayerObject& o, int lo, int hi) const {
    o.fit_first = o.first;
    o.fit_last = o.last;
    o.fit_top = o.top;
    const int reach = px(params_.fit_reach_cm);
    if (reach <= 0) return;
    const int row_lo = std::max(0, o.top - reach);
    const int row_hi = std::min(layer_.labels->rows - 1, o.top + 3 * (o.bottom - o.top) / 4);
    for (int direction : {-1, 1}) {
      const int start = direction < 0 ? o.first : o.last;
      // Columns start+direction ... as far as reach and lo..hi allow, stopping at a passing column.
      int far = start;
      for (int c = start + direction; c >= lo && c <= hi && std::abs(c - start) <= reach && !passes(c); c += direction) far = c;
      if (far == start) continue;
      // The band's pixels per column, gathered kChunk columns at a time from the object's edge column
      // (start) outwards, only as far as the walk below goes (it stops after column_gap columns that do
      // not continue the object); the same counts as gathering start..far at once.
      const int n = std::abs(far - start) + 1;  // columns start, start + direction, ..., far
      band_.assign(static_cast<std::size_t>(n), BandColumn{});
      int gathered = 0;
      // Sums of at most 65,535 per pixel over every other row: exact in 32 bits below 131,072 rows.
      const bool narrow_sums = row_hi - row_lo < 131072;
      const auto gather = [&](int until) {  // steps gathered..until-1 from start
        if (narrow_sums) {
          gather_band<std::uint32_t>(direction, start, n, gathered, until, row_lo, row_hi);
        } else {
          gather_band<std::uint64_t>(direction, start, n, gathered, until, row_lo, row_hi);
        }
      };
      auto mean_depth = [&](int step) {
        const BandColumn& b = band_[static_cast<std::size_t>(step)];
        return b.count > 0 ? static_cast<double>(b.depth_sum) / b.count : 0.0;
      };
      // First the columns a walk that takes none needs (most objects have nothing attached), then kChunk more.
      gather(1 + std::min(kChunk, std::max(1, params_.column_gap + 1)));
      // A piece continues the object: its mean depth is within fit_depth_step_mm of the last column taken.
      double previous_depth = mean_depth(0);
      int edge = start, gap = 0, occluded = 0, top = o.fit_top;
      int previous_count = band_[0].count;
      const int occlusion_gap = px(params_.fit_occlusion_gap_cm);
      for (int step = 1; step < n; ++step) {
        if (step >= gathered) gather(step + kChunk);
        const int c = start + direction * step;
        const BandColumn& b = band_[static_cast<std::size_t>(step)];
        const bool continues = b.count >= 2 && (previous_depth <= 0 || params_.fit_depth_step_mm <= 0 ||
                                                std::abs(mean_depth(step) - previous_depth) <= params_.fit_depth_step_mm);
        if (continues) {
          edge = c;
          gap = 0;
          occluded = 0;
          top = std::min(top, b.first_row);
          previous_depth = mean_depth(step);
          previous_count = b.count;
        } else if (occluded < occlusion_gap && nearer_in_band(c, row_lo, row_hi, std::max(2, previous_count / 2))) {
          ++occluded;
        } else if (++gap > params_.column_gap) {
          break;
        }
      }
      (direction < 0 ? o.fit_first : o.fit_last) = edge;
      o.fit_top = top;
    }
  }

  // fit(): at least `needed` pixels of nearer layers (labels 1..label-1) in column c, rows row_lo..row_hi,
  // every other one (the band's rows): something stands in front of the band there.
  bool nearer_in_band(int c, int row_lo, int row_hi, int needed) const {
    int nearer = 0;
    for (int y = row_lo; y <= row_hi && nearer < needed; y += 2) {
      const int label = layer_.labels->ptr<std::uint8_t>(y)[c];
      nearer += label > 0 && label < layer_.label;
    }
    return nearer >= needed;
  }

  // fit(): the band's pixels of the columns at steps gathered..until-1 (of n) from `start` in `direction`,
  // rows row_lo..row_hi, every other one, into band_. Left to right in memory (16 columns in SSE2 lanes
  // when band_16_lanes() allows, else one by one without a branch on the data), then stored by step.
  template <typename Sum>
  void gather_band(int direction, int start, int n, int& gathered, int until, int row_lo, int row_hi) const {
    const int from_step = gathered, to_step = std::min(until, n);
    if (to_step <= from_step) return;
    const int c0 = direction < 0 ? start - (to_step - 1) : start + from_step;  // leftmost column
    const int count = to_step - from_step;
    int in_count[kChunk + 1] = {}, first_row[kChunk + 1];
    Sum depth_sum[kChunk + 1] = {};
    std::fill(first_row, first_row + count, -1);
    const int layer_label = layer_.label;
#ifdef __SSE2__
    if (band_16_lanes<Sum>(count, row_hi)) {
      band_sse2(c0, count, row_lo, row_hi, in_count, first_row, depth_sum);
    } else
#endif
    {
      for (int y = row_lo; y <= row_hi; y += 2) {
        const std::uint8_t* label = layer_.labels->ptr<std::uint8_t>(y) + c0;
        const std::uint16_t* depth = layer_.depth_mm->ptr<std::uint16_t>(y) + c0;
        for (int j = 0; j < count; ++j) {
          const int in = label[j] == layer_label;
          first_row[j] = (in != 0 && first_row[j] < 0) ? y : first_row[j];
          in_count[j] += in;
          depth_sum[j] += static_cast<Sum>(in) * depth[j];
        }
      }
    }
    for (int j = 0; j < count; ++j) {
      const int step = direction < 0 ? to_step - 1 - j : from_step + j;
      band_[static_cast<std::size_t>(step)] = {in_count[j], first_row[j], static_cast<std::int64_t>(depth_sum[j])};
    }
    gathered = to_step;
  }

#ifdef __SSE2__
  // The 16-lane gather holds: at most 16 columns, an image at least 16 wide (the 16 columns read may
  // start left of c0), a label that is a byte, rows that are 16-bit, 32-bit depth sums.
  template <typename Sum>
  bool band_16_lanes(int count, int row_hi) const {
    return sizeof(Sum) == 4 && count <= 16 && layer_.labels->cols >= 16 && layer_.label >= 0 && layer_.label <= 255 &&
           row_hi <= 65535;
  }

  // gather_band()'s counts for columns c0..c0+count-1 in 16 lanes: lane i is column base + i, base =
  // min(c0, cols - 16) so that the 16 columns read lie inside the row. Per lane: the count in 8-bit lanes,
  // added into 16-bit ones every 255 rows (at most 65,535 rows every other one: 16 bits suffice); the
  // first row as a 16-bit row index kept while no earlier row held the layer; the depth sum in 32 bits.
  void band_sse2(int c0, int count, int row_lo, int row_hi, int* in_count, int* first_row,
                 std::uint32_t* depth_sum) const {
    const int base = std::min(c0, layer_.labels->cols - 16), offset = c0 - base;
    const __m128i layer_v = _mm_set1_epi8(static_cast<char>(layer_.label));
    const __m128i zero = _mm_setzero_si128();
    __m128i count8 = zero, count_lo = zero, count_hi = zero;  // 16-bit counts of lanes 0-7 and 8-15
    __m128i seen_lo = zero, seen_hi = zero, first_lo = zero, first_hi = zero;
    __m128i sum0 = zero, sum1 = zero, sum2 = zero, sum3 = zero;  // 32-bit sums of lanes 0-3, 4-7, 8-11, 12-15
    int pending = 0;  // rows in count8
    const auto flush = [&]() {
      count_lo = _mm_add_epi16(count_lo, _mm_unpacklo_epi8(count8, zero));
      count_hi = _mm_add_epi16(count_hi, _mm_unpackhi_epi8(count8, zero));
      count8 = zero;
      pending = 0;
    };
    for (int y = row_lo; y <= row_hi; y += 2) {
      const std::uint8_t* label = layer_.labels->ptr<std::uint8_t>(y) + base;
      const std::uint16_t* depth = layer_.depth_mm->ptr<std::uint16_t>(y) + base;
      const __m128i in = _mm_cmpeq_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(label)), layer_v);
      count8 = _mm_sub_epi8(count8, in);
      const __m128i in_lo = _mm_unpacklo_epi8(in, in), in_hi = _mm_unpackhi_epi8(in, in);
      const __m128i row = _mm_set1_epi16(static_cast<short>(y));
      first_lo = _mm_or_si128(first_lo, _mm_and_si128(_mm_andnot_si128(seen_lo, in_lo), row));
      first_hi = _mm_or_si128(first_hi, _mm_and_si128(_mm_andnot_si128(seen_hi, in_hi), row));
      seen_lo = _mm_or_si128(seen_lo, in_lo);
      seen_hi = _mm_or_si128(seen_hi, in_hi);
      const __m128i d_lo = _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(depth)), in_lo);
      const __m128i d_hi = _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(depth + 8)), in_hi);
      sum0 = _mm_add_epi32(sum0, _mm_unpacklo_epi16(d_lo, zero));
      sum1 = _mm_add_epi32(sum1, _mm_unpackhi_epi16(d_lo, zero));
      sum2 = _mm_add_epi32(sum2, _mm_unpacklo_epi16(d_hi, zero));
      sum3 = _mm_add_epi32(sum3, _mm_unpackhi_epi16(d_hi, zero));
      if (++pending == 255) flush();
    }
    flush();
    alignas(16) std::uint16_t counts[16], firsts[16], seen[16];
    alignas(16) std::uint32_t sums[16];
    _mm_store_si128(reinterpret_cast<__m128i*>(counts), count_lo);
    _mm_store_si128(reinterpret_cast<__m128i*>(counts + 8), count_hi);
    _mm_store_si128(reinterpret_cast<__m128i*>(firsts), first_lo);
    _mm_store_si128(reinterpret_cast<__m128i*>(firsts + 8), first_hi);
    _mm_store_si128(reinterpret_cast<__m128i*>(seen), seen_lo);
    _mm_store_si128(reinterpret_cast<__m128i*>(seen + 8), seen_hi);
    _mm_store_si128(reinterpret_cast<__m128i*>(sums), sum0);
    _mm_store_si128(reinterpret_cast<__m128i*>(sums + 4), sum1);
    _mm_store_si128(reinterpret_cast<__m128i*>(sums + 8), sum2);
    _mm_store_si128(reinterpret_cast<__m128i*>(sums + 12), sum3);
    for (int j = 0; j < count; ++j) {
      const int lane = offset + j;
      in_count[j] = counts[lane];
      first_row[j] = seen[lane] != 0 ? firsts[lane] : -1;
      depth_sum[j] = sums[lane];
    }
  }

  template <typename Sum>
  void band_sse2(int, int, int, int, int*, int*, Sum*) const {}  // 64-bit sums: never (band_16_lanes)
#endif

  // Step 2: neighbours whose fitted extents touch are one object when together no wider than a person.
  std::vector<LayerObject> join(const std::vector<LayerObject>& objects) const {
    std::vector<LayerObject> joined;
    for (const LayerObject& o : objects) {
      if (!joined.empty()) {
        LayerObject& previous = joined.back();
        // Pieces each too narrow to be a candidate alone join only in near layers (farther they are the
        // legs of furniture more often than a person's), with join_narrow_passing only when their passing
        // columns are together at least narrow_passing_width_cm wide (legs, not a chair's slats).
        const bool narrow = !wide_enough(previous) && !wide_enough(o);
        const bool touch = o.fit_first <= previous.fit_last + 1 &&
                           (!narrow || (layer_.depth_mm_mean < params_.join_narrow_layers_below_mm &&
                                        (!params_.join_narrow_passing || passing_cm(previous) + passing_cm(o) >= params_.narrow_passing_width_cm)));
        if (touch && cm(o.fit_last - previous.fit_first + 1) <= params_.max_person_width_cm) {
          const int fit_first = previous.fit_first, fit_top = std::min(previous.fit_top, o.fit_top);
          previous = span(previous.first, o.last);
          previous.fit_first = fit_first;
          previous.fit_last = o.fit_last;
          previous.fit_top = std::min(fit_top, previous.top);
          continue;
        }
      }
      joined.push_back(o);
    }
    return joined;
  }

  // Height (cm) of the top of column c above the object's lowest row; 0 without a run in its rows.
  double profile_cm(const LayerObject& o, int c) const {
    const ColumnRun& r = run(c);
    if (r.length() == 0 || r.bottom < o.top || r.top > o.bottom) return 0.0;
    return layer_.camera->height_cm(o.bottom - std::max(o.top, r.top) + 1, layer_.depth_mm_mean);
  }

  // Height (cm) above the object's lowest row of column c's highest pixel of the layer at or below the
  // object's fitted top; 0 without one.
  double top_profile_cm(const LayerObject& o, int c) const {
    for (int y = std::max(0, o.fit_top); y <= o.bottom; ++y) {
      if ((*layer_.labels)(y, c) == layer_.label) return layer_.camera->height_cm(o.bottom - y + 1, layer_.depth_mm_mean);
    }
    return 0.0;
  }

  // Median depth of the layer's pixels in column c's run (every row_step-th row); 0 when none.
  double column_depth_mm(int c, int row_step = 2) const {
    const ColumnRun& r = run(c);
    std::vector<std::uint16_t>& depths = depths_;  // reused: called for many columns of a layer
    depths.clear();
    for (int y = r.top; y >= 0 && y <= r.bottom; y += row_step) {
      if ((*layer_.labels)(y, c) == layer_.label) depths.push_back((*layer_.depth_mm)(y, c));
    }
    if (depths.empty()) return 0.0;
    std::nth_element(depths.begin(), depths.begin() + static_cast<std::ptrdiff_t>(depths.size() / 2), depths.end());
    return depths[depths.size() / 2];
  }

  // A cut column: the middle of the first and last columns of lo..hi where `near(c)` holds (one must).
  template <typename Near>
  static int middle_of(int lo, int hi, Near near) {
    int first = -1, last = -1;
    for (int c = lo; c <= hi; ++c) {
      if (!near(c)) continue;
      if (first < 0) first = c;
      last = c;
    }
    return (first + last + 1) / 2;
  }

  // The best place to cut o.fit_first..o.fit_last (the first column of the right piece), or -1: the
  // largest depth jump between neighbouring columns, else the deepest valley of the height profile, else
  // the largest step between the mean heights of a person-wide band on each side.
  int cut(const LayerObject& o, int min_piece) const {
    const int a = o.fit_first, b = o.fit_last;
    if (b - a + 1 < 2 * min_piece) return -1;
    const int lo = a + min_piece, hi = b - min_piece + 1;  // cut columns leaving both pieces wide enough
    if (params_.split_depth_jump_mm > 0) {
      int best = -1;
      double best_jump = params_.split_depth_jump_mm;
      double previous = column_depth_mm(lo - 1);
      for (int c = lo; c <= hi; ++c) {
        const double depth = column_depth_mm(c);
        if (depth > 0 && previous > 0 && std::abs(depth - previous) > best_jump) {
          best_jump = std::abs(depth - previous);
          best = c;
        }
        if (depth > 0) previous = depth;
      }
      if (best >= 0) return best;
    }
    std::vector<double> h(static_cast<std::size_t>(b - a + 1));
    for (int c = a; c <= b; ++c) h[static_cast<std::size_t>(c - a)] = profile_cm(o, c);
    auto at = [&](int c) { return h[static_cast<std::size_t>(c - a)]; };
    if (params_.split_valley_cm > 0) {
      std::vector<double> left(h.size()), right(h.size());
      for (std::size_t i = 0; i < h.size(); ++i) left[i] = std::max(h[i], i > 0 ? left[i - 1] : 0.0);
      for (std::size_t i = h.size(); i-- > 0;) right[i] = std::max(h[i], i + 1 < h.size() ? right[i + 1] : 0.0);
      double deepest = 0;
      for (int c = lo; c <= hi; ++c) {
        const std::size_t i = static_cast<std::size_t>(c - a);
        deepest = std::max(deepest, std::min(left[i], right[i]) - h[i]);
      }
      if (deepest >= params_.split_valley_cm) {
        // The middle of the columns within 2 cm of the deepest point of the valley.
        return middle_of(lo, hi, [&](int c) {
          const std::size_t i = static_cast<std::size_t>(c - a);
          return std::min(left[i], right[i]) - h[i] >= deepest - 2.0;
        });
      }
    }
    if (params_.split_step_cm > 0) {
      const int band = std::max(1, px(params_.min_part_width_cm));
      int best = -1;
      double best_step = params_.split_step_cm;
      for (int c = lo; c <= hi; ++c) {
        double sum_left = 0, sum_right = 0;
        int n_left = 0, n_right = 0;
        for (int x = std::max(a, c - band); x < c; ++x, ++n_left) sum_left += at(x);
        for (int x = c; x < std::min(b + 1, c + band); ++x, ++n_right) sum_right += at(x);
        const double step = std::abs(sum_left / std::max(1, n_left) - sum_right / std::max(1, n_right));
        if (step > best_step) {
          best_step = step;
          best = c;
        }
      }
      return best;
    }
    return -1;
  }

  // Heads (split_head_drop_cm; CandidateParams has the rule): the columns where a head tops the profile
  // h of o.fit_first..o.fit_last, left to right.
  std::vector<int> heads(const LayerObject& o, const std::vector<double>& h) const {
    const int n = static_cast<int>(h.size());
    const int head_px = std::max(2, px(params_.split_head_width_cm)), half = head_px / 2;
    const int min_gap = std::max(1, px(params_.min_part_width_cm));
    const double tallest = *std::max_element(h.begin(), h.end());
    const auto at = [&](int i) { return i >= 0 && i < n ? h[static_cast<std::size_t>(i)] : 0.0; };
    // Within head_px beyond `from` in direction `step`, the profile reaches top - drop (inside the extent,
    // or beyond it where the extent ends at the image's left or right border).
    const bool open_left = o.fit_first == 0, open_right = o.fit_last == width_ - 1;
    const auto drops = [&](int from, int step, double top) {
      for (int k = 1; k <= head_px; ++k) {
        const int j = from + step * k;
        if (j < 0) return open_left;
        if (j >= n) return open_right;
        if (at(j) <= top - params_.split_head_drop_cm) return true;
      }
      return false;
    };
    std::vector<int> found;
    for (int i = 0; i < n;) {
      const double top = at(i);
      bool peak = top > 0 && top >= 0.75 * tallest;
      for (int j = i - half; peak && j <= i + half; ++j) peak = at(j) <= top;
      if (!peak) {
        ++i;
        continue;
      }
      int end = i;  // the columns at this peak's height; the head is at their middle
      while (end + 1 < n && at(end + 1) == top) ++end;
      const int c = (i + end) / 2;
      int left = c, right = c;  // the head's top: the columns within 5 cm of its height
      while (left > 0 && at(left - 1) >= top - 5.0) --left;
      while (right + 1 < n && at(right + 1) >= top - 5.0) ++right;
      const double top_cm = cm(right - left + 1);
      if (right - left + 1 <= head_px && top_cm >= params_.split_head_min_width_cm && drops(left, -1, top) &&
          drops(right, 1, top)) {
        if (found.empty() || c - found.back() >= min_gap) {
          found.push_back(c);
        } else if (top > at(found.back())) {
          found.back() = c;
        }
      }
      i = end + 1;
    }
    for (int& c : found) c += o.fit_first;
    return found;
  }

  // The cut between two heads (the first column of the right piece), or -1 with fewer than two: between the
  // neighbouring heads whose lower one rises the most above the lowest point of the profile between them,
  // at the middle of the columns within 2 cm of that point, both pieces at least min_piece wide.
  int cut_heads(const LayerObject& o, int min_piece) const {
    const int a = o.fit_first, b = o.fit_last;
    std::vector<double> h(static_cast<std::size_t>(b - a + 1));
    for (int c = a; c <= b; ++c) h[static_cast<std::size_t>(c - a)] = top_profile_cm(o, c);
    const std::vector<int> found = heads(o, h);
    const auto at = [&](int c) { return h[static_cast<std::size_t>(c - a)]; };
    int best = -1;
    double best_dip = 0;
    for (std::size_t k = 0; k + 1 < found.size(); ++k) {
      const int lo = std::max(found[k] + 1, a + min_piece), hi = std::min(found[k + 1], b - min_piece + 1);
      if (lo > hi) continue;
      double lowest = std::numeric_limits<double>::max();
      for (int c = lo; c <= hi; ++c) lowest = std::min(lowest, at(c));
      const double dip = std::min(at(found[k]), at(found[k + 1])) - lowest;
      if (dip <= best_dip) continue;
      best_dip = dip;
      best = middle_of(lo, hi, [&](int c) { return at(c) <= lowest + 2.0; });
    }
    return best;
  }

  // Step 3: an object with two heads (split_head_drop_cm) is cut between them, else one wider than a person
  // where cut() says, and each piece again; the final pieces (with their passing columns) are appended to
  // `out`, nothing when the object is not cut. *by_heads tells whether the first cut was between heads.
  void split(const LayerObject& whole, std::vector<LayerObject>& out, int depth = 0, bool* by_heads = nullptr) const {
    if (depth > 4) return;
    const int min_piece = std::max(1, px(params_.min_part_width_cm));
    int c = split_heads_enabled() ? cut_heads(whole, min_piece) : -1;
    const bool heads = c >= 0;
    if (by_heads != nullptr) *by_heads = heads;
    if (c < 0 && split_wide_enabled() && cm(whole.fit_last - whole.fit_first + 1) > params_.max_person_width_cm) {
      c = cut(whole, min_piece);
    }
    if (c < 0) return;
    for (const auto& [lo, hi] : {std::pair<int, int>{whole.fit_first, c - 1}, std::pair<int, int>{c, whole.fit_last}}) {
      int first = -1, last = -1;
      for (int x = lo; x <= hi; ++x) {
        if (!passes(x)) continue;
        if (first < 0) first = x;
        last = x;
      }
      if (first < 0) continue;
      LayerObject piece = span(first, last);
      // Between heads the columns around the cut may hold an arm either person holds out: with
      // fit_across_head_cut each piece reaches over them up to the other piece's passing columns.
      if (heads && params_.fit_across_head_cut) {
        fit(piece, whole.fit_first, whole.fit_last);
      } else {
        fit(piece, lo, hi);
      }
      piece.part = true;
      piece.object = whole.object;
      if (!wide_enough(piece)) continue;
      const std::size_t before = out.size();
      split(piece, out, depth + 1);
      if (out.size() == before) out.push_back(piece);
    }
  }

  const LayerView& layer_;
  const CandidateParams& params_;
  const std::vector<ColumnRun>& runs_;
  const int width_;
  std::vector<char> passing_;
  // fit(): the band's pixels of one column (count, first row holding one, sum of their depths).
  struct BandColumn {
    int count = 0, first_row = -1;
    std::int64_t depth_sum = 0;  // at most 65,535 per pixel, half of the rows: int sums suffice below 65,536 rows
  };
  static constexpr int kChunk = 16;  // columns gathered at a time
  mutable std::vector<BandColumn> band_;
  mutable std::vector<std::uint16_t> depths_;  // column_depth_mm()'s depths
};

}  // namespace

LayerObjects layer_objects(const LayerView& layer, const CandidateParams& params) {
  ObjectShaper shaper(layer, params);
  return {shaper.objects(), shaper.passing()};
}

}  // namespace rdsf
