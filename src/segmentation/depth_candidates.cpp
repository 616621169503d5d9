#include "rdsf/segmentation/depth_candidates.hpp"

#include <algorithm>
#include <cstdlib>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace rdsf {

void scan_depth_candidate_row(const std::uint16_t* d, int width, const SegmentationParams& p, std::vector<int>& out) {
  const int n = p.n, range = p.range_threshold_mm, threshold = p.depth_threshold_mm;
  // Pixel j (with j + n < width) is a candidate when it follows a jump and the next n pixels stay in range.
  const auto holds = [&](int j) {
    const int value = d[j];
    for (int m = 1; m <= n; ++m) {
      if (std::abs(static_cast<int>(d[j + m]) - value) > range) return false;
    }
    return true;
  };
  int j = p.left_border_jump ? 0 : 1;
  // The left image border counts as a jump: an object cut by it is seeded like one entered from the
  // right (a right-border object is seeded by its own left edge).
  if (j == 0 && n < width) {
    if (holds(0)) out.push_back(d[0]);
    j = 1;
  }
#ifdef __SSE2__
  if (n >= 0 && threshold >= 0 && threshold < 65535) {
    const int end = width - n;  // j < end
    const __m128i limit = _mm_set1_epi16(static_cast<short>(threshold));
    const __m128i zero = _mm_setzero_si128();
    for (; j + 8 <= end; j += 8) {
      const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(d + j));
      const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(d + j - 1));
      const __m128i difference = _mm_or_si128(_mm_subs_epu16(a, b), _mm_subs_epu16(b, a));
      // Two mask bits per lane, set where |d[j] - d[j-1]| > threshold.
      unsigned jumps = static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi16(_mm_subs_epu16(difference, limit), zero))) ^ 0xFFFFu;
      while (jumps != 0) {
        const int lane = __builtin_ctz(jumps) / 2;
        jumps &= ~(3u << (2 * lane));
        if (holds(j + lane)) out.push_back(d[j + lane]);
      }
    }
  }
#endif
  for (; j + n < width; ++j) {
    if (std::abs(static_cast<int>(d[j]) - static_cast<int>(d[j - 1])) <= threshold) continue;
    if (holds(j)) out.push_back(d[j]);
  }
}

std::vector<int> scan_depth_candidates(const cv::Mat1w& depth_mm, const SegmentationParams& p) {
  std::vector<int> candidates;
  const int step = std::max(1, p.row_step);
  for (int row = 0; row < depth_mm.rows; row += step) {
    scan_depth_candidate_row(depth_mm.ptr<std::uint16_t>(row), depth_mm.cols, p, candidates);
  }
  return candidates;
}

std::vector<double> merge_depth_candidates(std::vector<int> raw, const SegmentationParams& p) {
  std::sort(raw.begin(), raw.end());
  std::vector<double> merged;
  auto it = raw.begin();
  if (it != raw.end() && *it == 0) {
    merged.push_back(0.0);  // every "no reading" candidate is one
    it = std::upper_bound(raw.begin(), raw.end(), 0);
  }
  while (it != raw.end()) {
    const int run_start = *it;
    double sum = 0;
    int count = 0;
    while (it != raw.end() && *it - run_start <= p.candidate_threshold_mm) {
      sum += *it;
      ++count;
      ++it;
    }
    merged.push_back(sum / count);
  }
  return merged;
}

}  // namespace rdsf
