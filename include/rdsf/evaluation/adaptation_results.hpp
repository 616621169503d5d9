#pragma once
// The adaptation benchmark's results.tsv (scripts/adaptation-benchmark.sh writes it, rdsf-adapt --chart
// reads it) and its picture: answers spent against TAR at FPPF <= 0.1, one curve per mode (none, negatives,
// candidate, track, retrain), each point the mean over the rooms of one budget (evaluation/curve_plot).
//
// The file: the header line below, then one row per room, mode and budget, tab-separated:
//   room  mode  budget  answers  propagated  propagated_wrong  tar  train_s
// room and mode are text without tabs (mode not empty); budget, propagated and propagated_wrong are whole
// numbers >= 0; answers >= 0 (a count); tar in [0, 1]; train_s >= 0 seconds. Numbers are below 1e9.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf {

struct AdaptationResult {
  std::string room, mode;
  long budget = 0;
  double answers = 0;
  long propagated = 0, propagated_wrong = 0;
  double tar = 0;      ///< TAR at FPPF <= 0.1 on the room's later frames
  double train_s = 0;  ///< rdsf-train's wall time, seconds
};

/// "room\tmode\tbudget\tanswers\tpropagated\tpropagated_wrong\ttar\ttrain_s"
const std::string& adaptation_results_header();

/// Parses the text of `path`; throws Error "PATH: line N: ..." on a missing header or a bad row.
std::vector<AdaptationResult> parse_adaptation_results(const std::string& text, const std::string& path);

/// Reads and parses `path`; throws Error naming it.
std::vector<AdaptationResult> read_adaptation_results(const std::string& path);

/// The benchmark's picture of `results` (the rule above); a mode with one budget is one marked point.
cv::Mat3b draw_adaptation_chart(const std::vector<AdaptationResult>& results);

}  // namespace rdsf
