#pragma once
// The detector's CSV output: frame,candidate,x,y,w,h,depth_mm,score (strict box in pixels; score empty
// without a model). Written through AtomicTextFile, flushed after every frame.
#include <optional>
#include <string>
#include <vector>

#include "candidates/candidate.hpp"
#include "core/atomic_file.hpp"

namespace rdsf {

class DetectionCsv {
 public:
  DetectionCsv(const std::string& path, bool overwrite);
  /// Writes one row per candidate of a frame and flushes. `scores` empty or one per candidate.
  void write_frame(const std::string& frame, const std::vector<Candidate>& candidates,
                   const std::vector<double>& scores = {});
  void commit() { file_.commit(); }

  static const char* header() { return "frame,candidate,x,y,w,h,depth_mm,score"; }

 private:
  AtomicTextFile file_;
};

}  // namespace rdsf
