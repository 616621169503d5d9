#pragma once
// CLEAR MOT tracking figures (Bernardin and Stiefelhagen 2008) for boxes: per frame, ground-truth people
// (with track ids) are matched to tracker hypotheses (with person ids) at IoU >= 0.5. A correspondence of the
// previous frame is kept while it still overlaps that much; the remaining pairs are matched greedily, largest
// IoU first. A mismatch is counted when a track is matched to another hypothesis id than the one it was last
// matched to.
//   MOTP = mean IoU of the matched pairs x 100
//   MOTA = 1 - (misses + false positives + mismatches) / ground-truth people
#include <map>
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf {

struct TrackedBox {
  cv::Rect box;
  int id = 0;  ///< track id (truth) or person id (hypothesis)
};

struct MotFigures {
  long truth = 0, matches = 0, misses = 0, false_positives = 0, mismatches = 0;
  double iou_sum = 0;
  double motp() const { return matches > 0 ? 100.0 * iou_sum / static_cast<double>(matches) : 0.0; }
  double mota() const {
    return truth > 0 ? 1.0 - static_cast<double>(misses + false_positives + mismatches) / static_cast<double>(truth)
                     : 0.0;
  }
};

class ClearMot {
 public:
  void add_frame(const std::vector<TrackedBox>& truth, const std::vector<TrackedBox>& hypotheses);
  const MotFigures& figures() const { return figures_; }

 private:
  MotFigures figures_;
  std::map<int, int> previous_;  ///< track id -> hypothesis id matched in the previous frame
  std::map<int, int> last_;      ///< track id -> hypothesis id it was last matched to (ever)
};

}  // namespace rdsf
