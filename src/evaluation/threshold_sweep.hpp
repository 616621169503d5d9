#pragma once
// Evaluation of one model over a recording with ground truth, for a sweep of threshold_classifier: the
// thesis's detection tables (with and without segmentation errors) and CLEAR MOT tracking figures, the
// tracker being rerun at every threshold on the detections that pass it.
#include <string>
#include <vector>

#include "evaluation/clear_mot.hpp"
#include "evaluation/detection_metrics.hpp"
#include "evaluation/ground_truth.hpp"
#include "frame/camera_model.hpp"
#include "tracking/tracker.hpp"

namespace rdsf {

/// What evaluation keeps of a frame: every candidate's box, depth, colour histogram and score.
struct EvaluatedCandidate {
  cv::Rect box;
  double depth_mm = 0;
  double score = 0;
  ColourHistogram histogram;
};

struct EvaluatedFrame {
  std::string frame;  ///< name as in boxes.csv
  std::int64_t index = 0;
  CameraModel camera;
  std::vector<EvaluatedCandidate> candidates;
};

struct SweepRow {
  DetectionFigures all;    ///< every ground-truth person
  DetectionFigures clean;  ///< without segmentation errors
  MotFigures mot;
};

struct SweepResult {
  std::string model;             ///< label, e.g. "tree2 v3"
  std::vector<SweepRow> rows;    ///< one per threshold, in the given order
  long segmentation_errors = 0;
  double fps = 0;                ///< whole-system frames per second measured while running it
  /// Row with the best MOTA (first of equals).
  const SweepRow& best_mota() const;
  /// TAR at the largest FPPF <= max_fppf (interpolated between sweep points is not done: the best row
  /// whose FPPF does not exceed it); 0 when none does.
  double tar_at_fppf(double max_fppf) const;
};

SweepResult sweep_thresholds(const std::vector<EvaluatedFrame>& frames, const GroundTruth& truth,
                             const std::vector<double>& thresholds, const TrackingParams& tracking,
                             const std::string& model_label);

/// Writes metrics.csv, summary.txt, summary.md (one Markdown row per model), roc.png and det.png into `dir` (created when missing); returns the
/// summary text (also what summary.txt holds).
std::string write_evaluation_report(const std::vector<SweepResult>& results, const std::string& dir,
                                    double operating_threshold);

}  // namespace rdsf
