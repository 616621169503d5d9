#include "rdsf/candidates/column_heights.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace rdsf {
namespace {

using Word = std::uint64_t;

// 1 in bit i when byte i of x is not zero.
inline unsigned nonzero_bytes(Word x) {
  const Word high = 0x8080808080808080ULL, low = 0x7F7F7F7F7F7F7F7FULL;
  const Word t = (((x & low) + low) | x) & high;
  return static_cast<unsigned>((t * 0x0002040810204081ULL) >> 56);
}

// Bit j when columns c0 + j of rows `above` and `row` differ (j < n <= 64).
inline Word changed_columns(const std::uint8_t* above, const std::uint8_t* row, int n) {
  Word mask = 0;
  int j = 0;
#ifdef __SSE2__
  for (; j + 16 <= n; j += 16) {
    const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(above + j));
    const __m128i y = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + j));
    const unsigned same = static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(x, y)));
    mask |= static_cast<Word>(~same & 0xFFFFu) << j;
  }
#endif
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__  // the first byte in memory is the word's lowest
  for (; j + 8 <= n; j += 8) {
    Word x, y;
    std::memcpy(&x, above + j, 8);
    std::memcpy(&y, row + j, 8);
    mask |= static_cast<Word>(nonzero_bytes(x ^ y)) << j;
  }
#endif
  for (; j < n; ++j) mask |= static_cast<Word>(above[j] != row[j]) << j;
  return mask;
}

// One pass over the label image, row by row (no transpose, no pass per layer). A column's segments (rows
// of one label) end where its label differs from the one above: 16 columns are compared at a time, and
// each segment is handed to its column's state when it ends, so every column sees its segments top to
// bottom, as the reference does (tests/support/reference_candidates.hpp). Per column, two bit sets over
// the labels replace the reference's per-layer flags:
//   farther bit L  some segment of a label > L since L's last segment (L's nothing_farther is false)
//   nearer bit L   some segment of a label in 1..L-1 since then (L's something_nearer is true)
// A segment of label s sets farther bits 1..s-1 and, when s > 0, nearer bits s+1..layer_count; for
// 1 <= s <= layer_count it then goes on with or restarts label s's run as the reference does and clears
// s's bits (a gap since L's last segment that set neither held missing readings only). Segments of label 0
// (no reading) change nothing (their run is slot 0's); labels above layer_count only mark the flags (their
// runs go to slot 0, which is never reported). Each segment is visited once instead of once per layer
// present in its column, with no other branch on the data. Words: 64-bit words of a bit set (labels
// 0..layer_count). Holes: some layer has a hole gap limit (the test costs the scan a
// tenth of its time, so a scan without limits leaves it out).
template <int Words, bool Holes>
class RunScanner {
 public:
  RunScanner(int width, int layer_count, int k, const std::vector<int>& occlusion_gap_px,
             const std::vector<int>& hole_gap_px)
      : width_(width), slots_(static_cast<std::size_t>(layer_count) + 1), k_(k) {
    occlusion_.assign(slots_, 0);
    hole_.assign(slots_, 0);
    for (std::size_t l = 1; l < slots_ && l < occlusion_gap_px.size(); ++l) occlusion_[l] = occlusion_gap_px[l];
    for (std::size_t l = 1; l < slots_ && l < hole_gap_px.size(); ++l) hole_[l] = hole_gap_px[l];
    for (int s = 0; s < 256; ++s) {
      slot_of_[s] = static_cast<std::uint8_t>(s >= 1 && s <= layer_count ? s : 0);
      for (int w = 0; w < Words; ++w) below_[s][w] = above_[s][w] = 0;
      for (int l = 1; l <= layer_count; ++l) {
        const Word bit = Word{1} << (l % 64);
        if (l < s) below_[s][l / 64] |= bit;
        if (s > 0 && l > s) above_[s][l / 64] |= bit;
      }
    }
    columns_.assign(static_cast<std::size_t>(width), Column{});
    runs_.assign(static_cast<std::size_t>(width) * slots_, Run{});
  }

  void scan(const cv::Mat1b& labels) {
    const int height = labels.rows;
    for (int r = 1; r < height; ++r) {
      const std::uint8_t* above = labels.ptr<std::uint8_t>(r - 1);
      const std::uint8_t* row = labels.ptr<std::uint8_t>(r);
      for (int c0 = 0; c0 < width_; c0 += 64) {
        Word changed = changed_columns(above + c0, row + c0, std::min(64, width_ - c0));
        while (changed != 0) {
          const int c = c0 + __builtin_ctzll(changed);
          changed &= changed - 1;
          Column& column = columns_[static_cast<std::size_t>(c)];
          segment(c, column, r - 1, above[c]);  // the segment ending here is of the label above
          column.first = r;
        }
      }
    }
    const std::uint8_t* last_row = labels.ptr<std::uint8_t>(height - 1);
    for (int c = 0; c < width_; ++c) segment(c, columns_[static_cast<std::size_t>(c)], height - 1, last_row[c]);
  }

  // The longest run of label l (1..layer_count) in column c.
  ColumnRun best(int l, int c) const {
    const Run& run = runs_[static_cast<std::size_t>(c) * slots_ + static_cast<std::size_t>(l)];
    return {run.top, run.length > 0 ? run.top + run.length - 1 : -1};
  }

 private:
  struct Column {
    Word farther[Words] = {};
    Word nearer[Words] = {};
    int first = 0;  // first row of the current segment (its label is the image's)
  };
  struct Run {
    int start = 0, last = -1;  // the run going on and the last row of the label in it (-1: none yet)
    int top = -1, length = 0;  // the longest run so far
  };

  // The segment of label s from column.first to `last` in column c.
  void segment(int c, Column& column, int last, int s) {
    // s == 0 (no reading) takes the same steps: below_[0] and above_[0] are empty, so it sets no bit, and
    // its run is slot 0's, which is never reported (no branch on the data).
    const int first = column.first;
    for (int w = 0; w < Words; ++w) {
      column.farther[w] |= below_[s][w];
      column.nearer[w] |= above_[s][w];
    }
    const int slot = slot_of_[s];
    const int word = slot / 64;
    const Word bit = Word{1} << (slot % 64);
    const bool nothing_farther = (column.farther[word] & bit) == 0;
    const bool something_nearer = (column.nearer[word] & bit) != 0;
    column.farther[word] &= ~bit;
    column.nearer[word] &= ~bit;
    Run& run = runs_[static_cast<std::size_t>(c) * slots_ + static_cast<std::size_t>(slot)];
    // The run's update without a branch on the data (masks: all ones where a condition holds).
    const int gap = first - run.last - 1;
    const int occluded = nothing_farther & something_nearer & (gap <= occlusion_[static_cast<std::size_t>(slot)]);
    const int holed = Holes ? nothing_farther & (something_nearer ^ 1) & (gap <= hole_[static_cast<std::size_t>(slot)]) : 0;
    const int restart = -((run.last < 0) | ((gap > k_) & (occluded ^ 1) & (holed ^ 1)));
    const int start = (first & restart) | (run.start & ~restart);
    run.start = start;
    run.last = last;
    const int length = last - start + 1;
    const int longer = -(length > run.length);
    run.top = (start & longer) | (run.top & ~longer);
    run.length = (length & longer) | (run.length & ~longer);
  }

  const int width_;
  const std::size_t slots_;  // labels 0..layer_count
  const int k_;
  std::vector<int> occlusion_;
  std::vector<int> hole_;
  std::uint8_t slot_of_[256];
  Word below_[256][Words], above_[256][Words];
  std::vector<Column> columns_;
  std::vector<Run> runs_;  // per column, per slot
};

template <int Words, bool Holes>
void scan_runs(const cv::Mat1b& labels, int layer_count, int k, const std::vector<int>& occlusion_gap_px,
               const std::vector<int>& hole_gap_px, std::vector<std::vector<ColumnRun>>& best) {
  RunScanner<Words, Holes> scanner(labels.cols, layer_count, k, occlusion_gap_px, hole_gap_px);
  scanner.scan(labels);
  for (int l = 1; l <= layer_count; ++l) {
    for (int c = 0; c < labels.cols; ++c) best[static_cast<std::size_t>(l)][static_cast<std::size_t>(c)] = scanner.best(l, c);
  }
}

// The bit sets' width for `counted` labels.
template <bool Holes>
void scan_with(const cv::Mat1b& labels, int counted, int k, const std::vector<int>& occlusion_gap_px,
               const std::vector<int>& hole_gap_px, std::vector<std::vector<ColumnRun>>& best) {
  if (counted < 64) {
    scan_runs<1, Holes>(labels, counted, k, occlusion_gap_px, hole_gap_px, best);
  } else if (counted < 128) {
    scan_runs<2, Holes>(labels, counted, k, occlusion_gap_px, hole_gap_px, best);
  } else {
    scan_runs<4, Holes>(labels, counted, k, occlusion_gap_px, hole_gap_px, best);
  }
}

}  // namespace

std::vector<std::vector<ColumnRun>> column_runs(const cv::Mat1b& labels, int layer_count, int k,
                                                const std::vector<int>& occlusion_gap_px,
                                                const std::vector<int>& hole_gap_px) {
  std::vector<std::vector<ColumnRun>> best(static_cast<std::size_t>(std::max(0, layer_count)) + 1,
                                           std::vector<ColumnRun>(static_cast<std::size_t>(labels.cols)));
  if (labels.empty() || layer_count <= 0) return best;
  // Labels are bytes: no pixel holds a label above 255, so those layers have no runs.
  const int counted = std::min(layer_count, 255);
  if (std::any_of(hole_gap_px.begin(), hole_gap_px.end(), [](int rows) { return rows > 0; })) {
    scan_with<true>(labels, counted, k, occlusion_gap_px, hole_gap_px, best);
  } else {
    scan_with<false>(labels, counted, k, occlusion_gap_px, hole_gap_px, best);
  }
  return best;
}

}  // namespace rdsf
