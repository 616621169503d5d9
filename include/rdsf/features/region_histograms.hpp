#pragma once
// The depth histograms of a feature spec's regions in a masked crop, as the Bhattacharyya coefficient
// needs them: per region r of area A and per bin b with c_b pixels, the root sqrt(float(c_b) / float(A)),
// kept twice: dense (bin_count values, zeros included) and sparse (only the non-zero bins, ascending).
//
// Counting: the window is cut into blocks of g x g pixels, g the greatest common divisor of the region
// geometry (the cell side for "rdsf"; gcd(min, step, stride) for "rdsf-rect", 8 by default), so that every
// region is a union of whole blocks. A block whose smallest and largest depth fall into the same bin is
// counted at once (bin_of is monotonic); in others the pixels below each bin edge between the smallest
// non-zero and the largest depth are counted with 8-wide comparisons (SSE2), or pixel by pixel without it.
// Blocks of 8 x 8 (SSE2) keep their rows in registers and visit only the occupied bins: the pass that
// counts the pixels below bin b's upper edge also finds the smallest depth at or above it, whose bin is the
// next occupied one. When every region is one such block, the occupied bins go straight to the slot.
// A region that is one block takes the block's counts; larger regions take four look-ups per bin in the
// integral histogram of the block counts (Porikli's integral histogram at block resolution: exact, as
// counts are integers).
//
// The coefficient of regions (i, j) is pair_value(): the sequential float sum over j's non-zero bins,
// ascending, of dense_i[b] * sparse_j[b], clamped to [0, 1]. Bins where either root is zero add exactly
// zero, so this equals the dense sum over all bins, and every caller gets the same bits for the same pair.
// pair_value_short() is the same sum for a j of at most 4 bins without branches on the data (FeatureSubset).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include <opencv2/core.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "rdsf/features/feature_spec.hpp"

namespace rdsf {

/// Root histograms of some regions, one slot per region.
struct RootHistograms {
  int bins = 0;
  std::vector<float> dense;             ///< slots x bins
  std::vector<std::uint16_t> nz_count;  ///< per slot: number of non-zero bins
  std::vector<std::uint8_t> nz_bin;     ///< slots x bins: the non-zero bins, ascending (first nz_count used)
  std::vector<float> nz_root;           ///< slots x bins: their roots

  void resize(int slots, int bin_count);
  const float* dense_of(int slot) const { return dense.data() + static_cast<std::size_t>(slot) * bins; }
  const std::uint8_t* nz_bin_of(int slot) const { return nz_bin.data() + static_cast<std::size_t>(slot) * bins; }
  const float* nz_root_of(int slot) const { return nz_root.data() + static_cast<std::size_t>(slot) * bins; }
};

/// The Bhattacharyya coefficient of the regions in slots i and j (see the header comment).
inline float pair_value(const RootHistograms& h, int slot_i, int slot_j) {
  const float* dense = h.dense_of(slot_i);
  const std::uint8_t* bin = h.nz_bin_of(slot_j);
  const float* root = h.nz_root_of(slot_j);
  const int n = h.nz_count[static_cast<std::size_t>(slot_j)];
  if (n == 1) {  // the common uniform region: 0 + x is x, so the same bits as the loop
    const float value = dense[bin[0]] * root[0];
    return value > 1.0f ? 1.0f : value;
  }
  float sum = 0.0f;
  for (int k = 0; k < n; ++k) sum += dense[bin[k]] * root[k];
  return sum > 1.0f ? 1.0f : sum;  // rounding can leave 1 + 1e-7; the sum is never negative
}

/// pair_value() without branches on the data, for a region j of at most 4 non-zero bins (nz_count <= 4)
/// in histograms of at least 4 bins: always 4 terms, the k-th dense_i[b_k] * root_k kept when k <
/// nz_count[j] and +0 otherwise (its bits and-ed with a mask; index 0 read instead), the four products in
/// SSE2 lanes (each an IEEE product, as the scalar one), summed lane by lane in order. Adding +0 leaves
/// the non-negative float sum as it was, so these are pair_value's bits.
inline float pair_value_short(const RootHistograms& h, int slot_i, int slot_j) {
  const float* dense = h.dense_of(slot_i);
  const std::uint8_t* bin = h.nz_bin_of(slot_j);
  const float* root = h.nz_root_of(slot_j);
  const unsigned n = h.nz_count[static_cast<std::size_t>(slot_j)];
#if defined(__SSE2__)
  const __m128i keep = _mm_cmplt_epi32(_mm_setr_epi32(0, 1, 2, 3), _mm_set1_epi32(static_cast<int>(n)));
  const unsigned k1 = 0u - static_cast<unsigned>(n > 1), k2 = 0u - static_cast<unsigned>(n > 2),
                 k3 = 0u - static_cast<unsigned>(n > 3);
  const __m128 d = _mm_setr_ps(dense[bin[0]], dense[bin[1] & k1], dense[bin[2] & k2], dense[bin[3] & k3]);
  const __m128 t = _mm_and_ps(_mm_mul_ps(d, _mm_loadu_ps(root)), _mm_castsi128_ps(keep));
  __m128 sum = _mm_add_ss(_mm_setzero_ps(), t);  // ((0 + t0) + t1) + t2) + t3, in this order
  sum = _mm_add_ss(sum, _mm_shuffle_ps(t, t, _MM_SHUFFLE(1, 1, 1, 1)));
  sum = _mm_add_ss(sum, _mm_movehl_ps(t, t));
  sum = _mm_add_ss(sum, _mm_shuffle_ps(t, t, _MM_SHUFFLE(3, 3, 3, 3)));
  const float value = _mm_cvtss_f32(sum);
  return value > 1.0f ? 1.0f : value;
#else
  float sum = 0.0f;
  for (unsigned k = 0; k < 4; ++k) {
    const std::uint32_t keep = 0u - static_cast<std::uint32_t>(k < n);  // all ones or zero
    const float term = dense[bin[k] & keep] * root[k];
    std::uint32_t bits = 0;
    std::memcpy(&bits, &term, sizeof bits);
    bits &= keep;
    float kept = 0.0f;
    std::memcpy(&kept, &bits, sizeof kept);
    sum += kept;
  }
  return sum > 1.0f ? 1.0f : sum;
#endif
}

class RegionHistogramBuilder {
 public:
  explicit RegionHistogramBuilder(const FeatureSpec& spec);

  const FeatureSpec& spec() const { return spec_; }
  /// Histogram bin of a depth value (0 = no reading).
  int bin_of(int depth_mm) const {
    return depth_mm <= 0 ? 0 : 1 + std::min(depth_mm / spec_.bin_width_mm, spec_.bin_count() - 2);
  }
  /// Side of the counting blocks.
  int block_px() const { return block_px_; }

  /// Histograms of every region; slot r holds region r. Throws Error on a crop of the wrong size.
  void compute_all(const cv::Mat1w& crop_depth_mm, RootHistograms& out) const;
  /// Histograms of the given regions; slot k holds regions[k].
  void compute(const cv::Mat1w& crop_depth_mm, const std::vector<int>& regions, RootHistograms& out) const;

 private:
  struct Geometry {
    int bx0, by0, bx1, by1;  // block range [bx0, bx1) x [by0, by1)
  };
  void check(const cv::Mat1w& crop) const;
  /// Adds the counts of block (bx, by) to `counts` (bin_count values); returns the bin when all its
  /// pixels share one, else -1.
  int count_block(const cv::Mat1w& crop, int bx, int by, std::uint32_t* counts) const;
  /// Counts of every block, then their integral: integral_[((by * (blocks_x + 1)) + bx) * bins + b].
  void build_integral(const cv::Mat1w& crop, std::vector<std::uint32_t>& integral) const;
  void finish_slot(const std::uint32_t* counts, int region, int slot, RootHistograms& out) const;
  /// The roots of every count for the region's area, or null when it has no table (very large areas).
  const float* roots_of(int region) const;
  static constexpr std::uint32_t kNoTable = 0xffffffffu;

  FeatureSpec spec_;
  int block_px_ = 8;
  int blocks_x_ = 0, blocks_y_ = 0;
  bool single_blocks_ = true;  ///< no region is larger than one block: no integral needed
  std::vector<FeatureRegion> regions_;
  std::vector<Geometry> geometry_;
  std::vector<std::uint8_t> lut_;  ///< depth (0..65535) -> bin
  std::vector<std::uint16_t> upper_edge_;  ///< per bin b: the smallest depth of a higher bin
  std::vector<float> root_table_;           ///< per distinct area A: sqrt(float(c) / float(A)), c = 0..A
  std::vector<std::uint32_t> root_offset_;  ///< per region: where its area's roots start (or kNoTable)
};

}  // namespace rdsf
