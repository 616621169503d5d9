#include "candidates/column_heights.hpp"

namespace rdsf {

std::vector<std::vector<ColumnRun>> column_runs(const cv::Mat1b& labels, int layer_count, int k) {
  const int width = labels.cols;
  std::vector<std::vector<ColumnRun>> best(static_cast<std::size_t>(layer_count) + 1,
                                           std::vector<ColumnRun>(static_cast<std::size_t>(width)));
  // The run in progress per (label, column): its first row and its last occupied row.
  std::vector<int> start(best.size() * static_cast<std::size_t>(width), -1);
  std::vector<int> last(best.size() * static_cast<std::size_t>(width), -1);
  for (int r = 0; r < labels.rows; ++r) {
    const std::uint8_t* row = labels.ptr<std::uint8_t>(r);
    for (int c = 0; c < width; ++c) {
      const int label = row[c];
      if (label == 0 || label > layer_count) continue;
      const std::size_t at = static_cast<std::size_t>(label) * static_cast<std::size_t>(width) +
                             static_cast<std::size_t>(c);
      if (last[at] < 0 || r - last[at] - 1 > k) start[at] = r;
      last[at] = r;
      ColumnRun& b = best[static_cast<std::size_t>(label)][static_cast<std::size_t>(c)];
      if (r - start[at] + 1 > b.length()) {
        b.top = start[at];
        b.bottom = r;
      }
    }
  }
  return best;
}

}  // namespace rdsf
