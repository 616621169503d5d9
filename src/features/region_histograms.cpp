#include "rdsf/features/region_histograms.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "rdsf/core/error.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rdsf {
namespace {

#if defined(__SSE2__)
int horizontal_sum(__m128i lanes16) {
  const __m128i sums = _mm_madd_epi16(lanes16, _mm_set1_epi16(1));  // 4 x int32
  const __m128i half = _mm_add_epi32(sums, _mm_shuffle_epi32(sums, _MM_SHUFFLE(1, 0, 3, 2)));
  return _mm_cvtsi128_si32(_mm_add_epi32(half, _mm_shuffle_epi32(half, _MM_SHUFFLE(2, 3, 0, 1))));
}

// The vector path takes blocks whose rows are whole 8-pixel vectors and whose per-lane counts fit 16 bits.
bool vector_block(int g) { return g % 8 == 0 && g <= 128; }

// Smallest, largest and smallest non-zero depth of a block of g x g pixels at (x0, y0), and its zeros
// (unsigned 16-bit order through the signed comparisons: the top bit flipped).
void block_summary(const cv::Mat1w& crop, int x0, int y0, int g, std::uint16_t& lo, std::uint16_t& hi,
                   std::uint16_t& nonzero_lo, int& zeros) {
  const __m128i flip = _mm_set1_epi16(static_cast<short>(0x8000)), zero = _mm_setzero_si128();
  __m128i mn = _mm_set1_epi16(0x7fff), mx = _mm_set1_epi16(static_cast<short>(0x8000)), nz = mn, count = zero;
  for (int y = y0; y < y0 + g; ++y) {
    const std::uint16_t* row = crop.ptr<std::uint16_t>(y) + x0;
    for (int x = 0; x < g; x += 8) {
      const __m128i raw = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + x));
      const __m128i is_zero = _mm_cmpeq_epi16(raw, zero);
      const __m128i v = _mm_xor_si128(raw, flip);
      mn = _mm_min_epi16(mn, v);
      mx = _mm_max_epi16(mx, v);
      nz = _mm_min_epi16(nz, _mm_xor_si128(_mm_or_si128(raw, is_zero), flip));  // zeros count as 65535
      count = _mm_sub_epi16(count, is_zero);
    }
  }
  alignas(16) std::uint16_t a[8], b[8], c[8];
  _mm_store_si128(reinterpret_cast<__m128i*>(a), _mm_xor_si128(mn, flip));
  _mm_store_si128(reinterpret_cast<__m128i*>(b), _mm_xor_si128(mx, flip));
  _mm_store_si128(reinterpret_cast<__m128i*>(c), _mm_xor_si128(nz, flip));
  lo = *std::min_element(a, a + 8);
  hi = *std::max_element(b, b + 8);
  nonzero_lo = *std::min_element(c, c + 8);
  zeros = horizontal_sum(count);
}

// Smallest of eight signed 16-bit lanes, in every lane.
__m128i lane_min(__m128i v) {
  v = _mm_min_epi16(v, _mm_shuffle_epi32(v, _MM_SHUFFLE(1, 0, 3, 2)));
  v = _mm_min_epi16(v, _mm_shuffle_epi32(v, _MM_SHUFFLE(2, 3, 0, 1)));
  return _mm_min_epi16(v, _mm_shufflelo_epi16(v, _MM_SHUFFLE(2, 3, 0, 1)));
}

// Sum of eight 16-bit lanes each below 256 (their high bytes zero: the sum of the 16 bytes).
int small_lane_sum(__m128i v) {
  const __m128i halves = _mm_sad_epu8(v, _mm_setzero_si128());
  return _mm_cvtsi128_si32(_mm_add_epi32(halves, _mm_unpackhi_epi64(halves, halves)));
}

// The occupied bins of an 8 x 8 block at (x0, y0), ascending, with their pixel counts (> 0); returns how
// many. Its eight rows stay in registers, kept only as v = depth ^ 0x8000 (unsigned order in signed
// lanes; a depth of 0 is v = -32768): one pass finds the smallest and largest depth; a block of one bin
// ends there. Otherwise one more pass finds the zeros (v == -32768) and the smallest non-zero depth (the
// minimum of v - 1, wrapping, which sends the zeros to the top); then, from the lowest occupied non-zero
// bin b up to the largest depth's bin, one pass per OCCUPIED bin counts the pixels below b's upper edge e
// and finds the smallest depth at or above e: the unsigned minimum of depth - e (mod 2^16, where the
// depths below e wrap above every other), whose bin is the next occupied one (empty bins in between cost
// nothing). The counts are those of the pixel-by-pixel histogram: differences of "pixels below an edge",
// bin_of being monotonic.
inline int block_bins_8(const cv::Mat1w& crop, int x0, int y0, const std::uint8_t* lut, const std::uint16_t* upper_edge,
                 std::uint8_t* bin, std::uint32_t* count) {
  const __m128i flip = _mm_set1_epi16(static_cast<short>(0x8000)), ones = _mm_set1_epi16(-1);
  __m128i v[8];
  __m128i mn = _mm_set1_epi16(0x7fff), mx = flip;
  for (int y = 0; y < 8; ++y) {
    v[y] = _mm_xor_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(crop.ptr<std::uint16_t>(y0 + y) + x0)), flip);
    mn = _mm_min_epi16(mn, v[y]);
    mx = _mm_max_epi16(mx, v[y]);
  }
  // Both reductions at once: lanes 0-3 from the minima, 4-7 from the complemented maxima (max = ~min(~v)).
  const __m128i not_mx = _mm_xor_si128(mx, ones);
  __m128i both = _mm_unpacklo_epi64(_mm_min_epi16(mn, _mm_shuffle_epi32(mn, _MM_SHUFFLE(1, 0, 3, 2))),
                                    _mm_min_epi16(not_mx, _mm_shuffle_epi32(not_mx, _MM_SHUFFLE(1, 0, 3, 2))));
  both = _mm_min_epi16(both, _mm_shuffle_epi32(both, _MM_SHUFFLE(2, 3, 0, 1)));
  both = _mm_min_epi16(both, _mm_srli_epi32(both, 16));  // lanes 0 and 4 hold the two results
  const int lo = (_mm_extract_epi16(both, 0) & 0xffff) ^ 0x8000;
  const int hi = (_mm_extract_epi16(both, 4) & 0xffff) ^ 0x7fff;
  const int last = lut[hi];
  if (lut[lo] == last) {
    bin[0] = static_cast<std::uint8_t>(last);
    count[0] = 64;
    return 1;
  }
  __m128i nz = _mm_set1_epi16(0x7fff), zeros_v = _mm_setzero_si128();  // only blocks of several bins need these
  for (int y = 0; y < 8; ++y) {
    zeros_v = _mm_sub_epi16(zeros_v, _mm_cmpeq_epi16(v[y], flip));
    nz = _mm_min_epi16(nz, _mm_add_epi16(v[y], ones));  // v - 1: depth 0 -> 32767, depth d > 0 -> d - 32769
  }
  int n = 0;
  const int zeros = small_lane_sum(zeros_v);
  if (zeros > 0) {
    bin[0] = 0;
    count[0] = static_cast<std::uint32_t>(zeros);
    n = 1;
  }
  int below = zeros;
  int b = lut[((_mm_cvtsi128_si32(lane_min(nz)) + 1) & 0xffff) ^ 0x8000];
  while (b < last) {
    const int edge = upper_edge[b];
    const __m128i limit = _mm_set1_epi16(static_cast<short>(edge ^ 0x8000));
    __m128i under = _mm_setzero_si128(), above_min = _mm_set1_epi16(0x7fff);
    for (int y = 0; y < 8; ++y) {
      under = _mm_sub_epi16(under, _mm_cmplt_epi16(v[y], limit));
      // (v - limit) is depth - edge mod 2^16; ^ 0x8000 makes its unsigned order signed
      above_min = _mm_min_epi16(above_min, _mm_xor_si128(_mm_sub_epi16(v[y], limit), flip));
    }
    const int c = small_lane_sum(under);
    bin[n] = static_cast<std::uint8_t>(b);
    count[n] = static_cast<std::uint32_t>(c - below);
    ++n;
    below = c;
    b = lut[(((_mm_cvtsi128_si32(lane_min(above_min)) & 0xffff) ^ 0x8000) + edge) & 0xffff];
  }
  bin[n] = static_cast<std::uint8_t>(last);
  count[n] = static_cast<std::uint32_t>(64 - below);
  return n + 1;
}

// Pixels of the block with a depth below `edge`.
int count_below(const cv::Mat1w& crop, int x0, int y0, int g, std::uint16_t edge) {
  const __m128i flip = _mm_set1_epi16(static_cast<short>(0x8000));
  const __m128i limit = _mm_set1_epi16(static_cast<short>(edge ^ 0x8000));
  __m128i count = _mm_setzero_si128();
  for (int y = y0; y < y0 + g; ++y) {
    const std::uint16_t* row = crop.ptr<std::uint16_t>(y) + x0;
    for (int x = 0; x < g; x += 8) {
      const __m128i v = _mm_xor_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(row + x)), flip);
      count = _mm_sub_epi16(count, _mm_cmplt_epi16(v, limit));
    }
  }
  return horizontal_sum(count);
}
#endif

}  // namespace

void RootHistograms::resize(int slots, int bin_count) {
  bins = bin_count;
  const std::size_t n = static_cast<std::size_t>(slots) * static_cast<std::size_t>(bin_count);
  dense.resize(n);  // every slot is written whole by finish_slot
  nz_count.resize(static_cast<std::size_t>(slots));
  nz_bin.resize(n);
  nz_root.resize(n);
}

RegionHistogramBuilder::RegionHistogramBuilder(const FeatureSpec& spec) : spec_(spec) {
  spec_.validate();
  block_px_ = spec_.layout == FeatureSpec::Layout::Cells
                  ? spec_.cell_px
                  : std::gcd(spec_.rect_min_px, std::gcd(spec_.rect_step_px, spec_.rect_stride_px));
  blocks_x_ = spec_.window_width_px / block_px_;
  blocks_y_ = spec_.window_height_px / block_px_;
  regions_ = spec_.regions();
  for (const FeatureRegion& r : regions_) {
    geometry_.push_back({r.x / block_px_, r.y / block_px_, (r.x + r.width) / block_px_, (r.y + r.height) / block_px_});
    if (r.width != block_px_ || r.height != block_px_) single_blocks_ = false;
  }
  // sqrt(float(c) / float(A)) for every count c of every area A (up to 65536 pixels), computed once.
  std::vector<std::pair<int, std::uint32_t>> tables;  // area -> offset
  for (const FeatureRegion& r : regions_) {
    std::uint32_t offset = kNoTable;
    for (const auto& [area, at] : tables) {
      if (area == r.area()) offset = at;
    }
    if (offset == kNoTable && r.area() <= 65536) {
      offset = static_cast<std::uint32_t>(root_table_.size());
      tables.emplace_back(r.area(), offset);
      for (int c = 0; c <= r.area(); ++c) {
        root_table_.push_back(std::sqrt(static_cast<float>(c) / static_cast<float>(r.area())));
      }
    }
    root_offset_.push_back(offset);
  }
  lut_.resize(65536);
  for (int d = 0; d < 65536; ++d) lut_[static_cast<std::size_t>(d)] = static_cast<std::uint8_t>(bin_of(d));
  upper_edge_.assign(static_cast<std::size_t>(spec_.bin_count()), 65535);
  for (int d = 1; d < 65536; ++d) {  // where the bin steps up from b, d is the smallest depth above b
    for (int b = lut_[static_cast<std::size_t>(d - 1)]; b < lut_[static_cast<std::size_t>(d)]; ++b) {
      upper_edge_[static_cast<std::size_t>(b)] = static_cast<std::uint16_t>(d);
    }
  }
}

void RegionHistogramBuilder::check(const cv::Mat1w& crop) const {
  if (crop.cols != spec_.window_width_px || crop.rows != spec_.window_height_px) {
    throw Error("RDSF: crop is " + std::to_string(crop.cols) + "x" + std::to_string(crop.rows) +
                ", the feature spec needs " + std::to_string(spec_.window_width_px) + "x" +
                std::to_string(spec_.window_height_px));
  }
}

int RegionHistogramBuilder::count_block(const cv::Mat1w& crop, int bx, int by, std::uint32_t* counts) const {
  const int g = block_px_, x0 = bx * g, y0 = by * g;
  const std::uint8_t* lut = lut_.data();
#if defined(__SSE2__)
  if (g == 8) {
    std::uint8_t bin[256];
    std::uint32_t count[256];
    const int n = block_bins_8(crop, x0, y0, lut, upper_edge_.data(), bin, count);
    for (int k = 0; k < n; ++k) counts[bin[k]] += count[k];
    return n == 1 ? bin[0] : -1;
  }
  if (vector_block(g)) {
    std::uint16_t lo = 0, hi = 0, nonzero_lo = 0;
    int zeros = 0;
    block_summary(crop, x0, y0, g, lo, hi, nonzero_lo, zeros);
    if (lut[lo] == lut[hi]) {  // bin_of is monotonic: every pixel is in this bin
      counts[lut[lo]] += static_cast<std::uint32_t>(g * g);
      return lut[lo];
    }
    // The non-zero depths span bins first..last: count the pixels below each bin's upper edge in between
    // (bins outside that span are empty), differences give the bins.
    counts[0] += static_cast<std::uint32_t>(zeros);
    int below = zeros;
    const int first = lut[nonzero_lo], last = lut[hi];
    for (int b = first; b < last; ++b) {
      const int c = count_below(crop, x0, y0, g, upper_edge_[static_cast<std::size_t>(b)]);
      counts[b] += static_cast<std::uint32_t>(c - below);
      below = c;
    }
    counts[last] += static_cast<std::uint32_t>(g * g - below);
    return -1;
  }
#endif
  std::uint16_t lo = 65535, hi = 0;
  for (int y = y0; y < y0 + g; ++y) {
    const std::uint16_t* row = crop.ptr<std::uint16_t>(y) + x0;
    for (int x = 0; x < g; ++x) {
      lo = std::min(lo, row[x]);
      hi = std::max(hi, row[x]);
    }
  }
  if (lut[lo] == lut[hi]) {
    counts[lut[lo]] += static_cast<std::uint32_t>(g * g);
    return lut[lo];
  }
  // Runs of equal bins: neighbouring pixels mostly share one, and a run costs one store.
  for (int y = y0; y < y0 + g; ++y) {
    const std::uint16_t* row = crop.ptr<std::uint16_t>(y) + x0;
    std::uint8_t current = lut[row[0]];
    std::uint32_t run = 0;
    for (int x = 0; x < g; ++x) {
      const std::uint8_t b = lut[row[x]];
      if (b != current) {
        counts[current] += run;
        current = b;
        run = 0;
      }
      ++run;
    }
    counts[current] += run;
  }
  return -1;
}

void RegionHistogramBuilder::build_integral(const cv::Mat1w& crop, std::vector<std::uint32_t>& integral) const {
  const std::size_t bins = static_cast<std::size_t>(spec_.bin_count());
  const std::size_t stride = static_cast<std::size_t>(blocks_x_ + 1) * bins;
  integral.assign(static_cast<std::size_t>(blocks_y_ + 1) * stride, 0u);
  std::vector<std::uint32_t> counts(bins);
  for (int by = 0; by < blocks_y_; ++by) {
    for (int bx = 0; bx < blocks_x_; ++bx) {
      std::fill(counts.begin(), counts.end(), 0u);
      count_block(crop, bx, by, counts.data());
      std::uint32_t* out = integral.data() + static_cast<std::size_t>(by + 1) * stride + (bx + 1) * bins;
      const std::uint32_t* up = out - stride;
      const std::uint32_t* left = out - bins;
      const std::uint32_t* diagonal = up - bins;
      for (std::size_t b = 0; b < bins; ++b) out[b] = counts[b] + up[b] + left[b] - diagonal[b];
    }
  }
}

const float* RegionHistogramBuilder::roots_of(int region) const {
  const std::uint32_t offset = root_offset_[static_cast<std::size_t>(region)];
  return offset == kNoTable ? nullptr : root_table_.data() + offset;
}

void RegionHistogramBuilder::finish_slot(const std::uint32_t* counts, int region, int slot, RootHistograms& out) const {
  const int area = regions_[static_cast<std::size_t>(region)].area();
  const float* table = roots_of(region);
  const int bins = out.bins;
  const std::size_t base = static_cast<std::size_t>(slot) * static_cast<std::size_t>(bins);
  float* dense = out.dense.data() + base;
  std::uint8_t* nz_bin = out.nz_bin.data() + base;
  float* nz_root = out.nz_root.data() + base;
  const float area_f = static_cast<float>(area);
  int n = 0;
  for (int b = 0; b < bins; ++b) {
    if (counts[b] == 0) {
      dense[b] = 0.0f;
      continue;
    }
    const float root = table != nullptr ? table[counts[b]] : std::sqrt(static_cast<float>(counts[b]) / area_f);
    dense[b] = root;
    nz_bin[n] = static_cast<std::uint8_t>(b);
    nz_root[n] = root;
    ++n;
  }
  out.nz_count[static_cast<std::size_t>(slot)] = static_cast<std::uint16_t>(n);
}

void RegionHistogramBuilder::compute(const cv::Mat1w& crop, const std::vector<int>& regions,
                                     RootHistograms& out) const {
  check(crop);
  const int bins = spec_.bin_count();
  out.resize(static_cast<int>(regions.size()), bins);
#if defined(__SSE2__)
  if (single_blocks_ && block_px_ == 8) {  // each region one 8 x 8 block: its occupied bins straight to the slot
    // Every region has the area 64: the one root table, sqrt(float(c) / 64.0f). The pointers are locals
    // so that the byte stores (which may alias anything) do not make the compiler reload them.
    const float* table = root_table_.data();
    const std::uint8_t* lut = lut_.data();
    const std::uint16_t* upper_edge = upper_edge_.data();
    const Geometry* geometry = geometry_.data();
    std::uint8_t* nz_bin = out.nz_bin.data();
    float* nz_root = out.nz_root.data();
    float* dense = out.dense.data();
    std::uint16_t* nz_count = out.nz_count.data();
    const std::size_t stride = static_cast<std::size_t>(bins);
    std::uint32_t count[256];
    const __m128 zero = _mm_setzero_ps();
    for (std::size_t k = 0; k < regions.size(); ++k, nz_bin += stride, nz_root += stride, dense += stride) {
      const Geometry& g = geometry[regions[k]];
      const int n = block_bins_8(crop, g.bx0 * 8, g.by0 * 8, lut, upper_edge, nz_bin, count);
      if (bins >= 4) {  // whole vectors, the last one overlapping the one before
        for (int b = 0; b + 4 < bins; b += 4) _mm_storeu_ps(dense + b, zero);
        _mm_storeu_ps(dense + bins - 4, zero);
      } else {
        for (int b = 0; b < bins; ++b) dense[b] = 0.0f;
      }
      for (int i = 0; i < n; ++i) {
        const float root = table[count[i]];
        dense[nz_bin[i]] = root;
        nz_root[i] = root;
      }
      nz_count[k] = static_cast<std::uint16_t>(n);
    }
    return;
  }
#endif
  thread_local std::vector<std::uint32_t> counts, integral;  // reused: no allocation per crop
  counts.resize(static_cast<std::size_t>(bins));
  if (single_blocks_) {
    for (std::size_t k = 0; k < regions.size(); ++k) {
      const Geometry& g = geometry_[static_cast<std::size_t>(regions[k])];
      std::fill(counts.begin(), counts.end(), 0u);
      const int bin = count_block(crop, g.bx0, g.by0, counts.data());
      if (bin >= 0) {  // one bin: root sqrt(A / A) = 1, the same bits finish_slot would give
        const std::size_t base = k * static_cast<std::size_t>(bins);
        std::fill(out.dense.begin() + static_cast<long>(base), out.dense.begin() + static_cast<long>(base) + bins, 0.0f);
        out.dense[base + static_cast<std::size_t>(bin)] = 1.0f;
        out.nz_bin[base] = static_cast<std::uint8_t>(bin);
        out.nz_root[base] = 1.0f;
        out.nz_count[k] = 1;
      } else {
        finish_slot(counts.data(), regions[k], static_cast<int>(k), out);
      }
    }
    return;
  }
  build_integral(crop, integral);
  const std::size_t stride = static_cast<std::size_t>(blocks_x_ + 1) * static_cast<std::size_t>(bins);
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const std::size_t r = static_cast<std::size_t>(regions[k]);
    const Geometry& g = geometry_[r];
    const std::uint32_t* a = integral.data() + static_cast<std::size_t>(g.by0) * stride + g.bx0 * bins;
    const std::uint32_t* b = integral.data() + static_cast<std::size_t>(g.by0) * stride + g.bx1 * bins;
    const std::uint32_t* c = integral.data() + static_cast<std::size_t>(g.by1) * stride + g.bx0 * bins;
    const std::uint32_t* d = integral.data() + static_cast<std::size_t>(g.by1) * stride + g.bx1 * bins;
    for (int bin = 0; bin < bins; ++bin) counts[static_cast<std::size_t>(bin)] = d[bin] - b[bin] - c[bin] + a[bin];
    finish_slot(counts.data(), static_cast<int>(r), static_cast<int>(k), out);
  }
}

void RegionHistogramBuilder::compute_all(const cv::Mat1w& crop, RootHistograms& out) const {
  std::vector<int> all(regions_.size());
  std::iota(all.begin(), all.end(), 0);
  compute(crop, all, out);
}

}  // namespace rdsf
