#include "rdsf/candidates/column_heights.hpp"

#include <cstdint>
#include <cstring>

namespace rdsf {
namespace {

struct Segment {
  int label, first, last;  // rows first..last of one label
};

// The last row of the run of equal labels that starts at `r`: eight labels compared at a time (the
// first differing byte of the XOR with the run's label repeated), then byte by byte at the end.
int run_end(const std::uint8_t* column, int r, int height) {
  const std::uint64_t repeated = 0x0101010101010101ULL * column[r];
  int next = r + 1;
  while (next + 8 <= height) {
    std::uint64_t word;
    std::memcpy(&word, column + next, 8);
    const std::uint64_t differ = word ^ repeated;
    if (differ != 0) {
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
      return next + __builtin_ctzll(differ) / 8 - 1;  // the first byte in memory is the lowest
#else
      return next + __builtin_clzll(differ) / 8 - 1;
#endif
    }
    next += 8;
  }
  while (next < height && column[next] == column[r]) ++next;
  return next - 1;
}

}  // namespace

std::vector<std::vector<ColumnRun>> column_runs(const cv::Mat1b& labels, int layer_count, int k,
                                                const std::vector<int>& occlusion_gap_px) {
  const int width = labels.cols, height = labels.rows;
  std::vector<std::vector<ColumnRun>> best(static_cast<std::size_t>(layer_count) + 1,
                                           std::vector<ColumnRun>(static_cast<std::size_t>(width)));
  // Columns as rows: one contiguous pass each.
  cv::Mat1b columns;
  cv::transpose(labels, columns);
  std::vector<Segment> segments;
  std::vector<char> present(static_cast<std::size_t>(layer_count) + 1);
  for (int c = 0; c < width; ++c) {
    const std::uint8_t* column = columns.ptr<std::uint8_t>(c);
    segments.clear();
    std::fill(present.begin(), present.end(), 0);
    for (int r = 0; r < height;) {
      const int label = column[r];
      const int end = run_end(column, r, height);
      segments.push_back({label, r, end});
      if (label > 0 && label <= layer_count) present[static_cast<std::size_t>(label)] = 1;
      r = end + 1;
    }
    for (int label = 1; label <= layer_count; ++label) {
      if (!present[static_cast<std::size_t>(label)]) continue;
      const int occlusion_limit =
          static_cast<std::size_t>(label) < occlusion_gap_px.size() ? occlusion_gap_px[static_cast<std::size_t>(label)] : 0;
      ColumnRun& b = best[static_cast<std::size_t>(label)][static_cast<std::size_t>(c)];
      int start = -1, last = -1;
      // Since `last`: no pixel of a farther layer, and some of a nearer one (missing readings are allowed
      // too: a Kinect leaves a shadow of no reading beside what stands in front).
      bool nothing_farther = true, something_nearer = false;
      for (const Segment& s : segments) {
        if (s.label != label) {
          if (s.label > label) nothing_farther = false;
          if (s.label > 0 && s.label < label) something_nearer = true;
          continue;
        }
        const int gap = s.first - last - 1;
        const bool occluded = nothing_farther && something_nearer && gap <= occlusion_limit;
        if (start < 0 || (gap > k && !occluded)) start = s.first;
        last = s.last;
        nothing_farther = true;
        something_nearer = false;
        if (last - start + 1 > b.length()) {
          b.top = start;
          b.bottom = last;
        }
      }
    }
  }
  return best;
}

}  // namespace rdsf
