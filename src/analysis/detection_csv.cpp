#include "rdsf/analysis/detection_csv.hpp"

#include <cmath>
#include <cstdio>

namespace rdsf {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string DetectionCsv::header(bool with_model) {
  return with_model ? "frame,candidate,x,y,w,h,depth_mm,score,person,distance_cm"
                    : "frame,candidate,x,y,w,h,depth_mm,score";
}

DetectionCsv::DetectionCsv(const std::string& path, bool overwrite, bool with_model, BoxKind box)
    : file_(path, overwrite), with_model_(with_model), box_(box) {
  file_.stream() << header(with_model) << "\n";
  file_.flush();
}

void DetectionCsv::write_frame(const std::string& frame, const std::vector<Candidate>& candidates,
                               const std::vector<CandidateOutcome>& outcomes) {
  auto& out = file_.stream();
  const std::string name = csv_field(frame);
  char number[32];
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const cv::Rect& b = reported_box(candidates[i], box_);
    out << name << ',' << i << ',' << b.x << ',' << b.y << ',' << b.width << ',' << b.height << ','
        << std::lround(candidates[i].layer_depth_mm) << ',';
    if (i < outcomes.size()) {
      std::snprintf(number, sizeof number, "%.4f", outcomes[i].score);
      out << number;
    }
    if (with_model_) {
      out << ',';
      if (i < outcomes.size() && outcomes[i].person != 0) {
        std::snprintf(number, sizeof number, "%.1f", outcomes[i].distance_cm);
        out << outcomes[i].person << ',' << number;
      } else {
        out << ',';
      }
    }
    out << '\n';
  }
  file_.flush();
}

}  // namespace rdsf
