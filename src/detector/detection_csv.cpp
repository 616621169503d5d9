#include "detector/detection_csv.hpp"

#include <cmath>

namespace rdsf {

DetectionCsv::DetectionCsv(const std::string& path, bool overwrite) : file_(path, overwrite) {
  file_.stream() << header() << "\n";
  file_.flush();
}

void DetectionCsv::write_frame(const std::string& frame, const std::vector<Candidate>& candidates,
                               const std::vector<double>& scores) {
  auto& out = file_.stream();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const cv::Rect& b = candidates[i].strict_box;
    out << frame << ',' << i << ',' << b.x << ',' << b.y << ',' << b.width << ',' << b.height << ','
        << std::lround(candidates[i].layer_depth_mm) << ',';
    if (i < scores.size()) out << scores[i];
    out << '\n';
  }
  file_.flush();
}

}  // namespace rdsf
