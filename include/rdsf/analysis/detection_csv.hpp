#pragma once
// The detector's CSV output, one row per candidate:
//   frame,candidate,x,y,w,h,depth_mm,score                       (no model: score empty)
//   frame,candidate,x,y,w,h,depth_mm,score,person,distance_cm    (with a model)
// x,y,w,h = the reported box in pixels (the fitted box, or the strict box with BoxKind::strict); person = tracked person id when the candidate is a detection (score >=
// threshold), else empty; distance_cm = distance that person has covered so far. Written through
// AtomicTextFile (FILE.partial, renamed when complete), flushed after every frame.
#include <string>
#include <vector>

#include "rdsf/candidates/candidate.hpp"
#include "rdsf/core/atomic_file.hpp"

namespace rdsf {

struct CandidateOutcome {
  double score = 0;
  int person = 0;          ///< 0: not a detection
  double distance_cm = 0;  ///< of that person so far
};

class DetectionCsv {
 public:
  DetectionCsv(const std::string& path, bool overwrite, bool with_model, BoxKind box = BoxKind::fitted);
  /// Writes one row per candidate and flushes. `outcomes` is empty without a model, else one per candidate.
  void write_frame(const std::string& frame, const std::vector<Candidate>& candidates,
                   const std::vector<CandidateOutcome>& outcomes = {});
  void commit() { file_.commit(); }

  static std::string header(bool with_model);

 private:
  AtomicTextFile file_;
  bool with_model_;
  BoxKind box_;
};

/// A CSV field: quoted (with doubled quotes) when it holds a comma, quote or line break.
std::string csv_field(const std::string& text);

}  // namespace rdsf
