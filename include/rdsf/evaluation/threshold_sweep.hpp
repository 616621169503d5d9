#pragma once
// Evaluation of one model over a recording with ground truth:
//   - the exact detection curve (the thesis's figures at every distinct score: exact_curve.hpp), from which
//     TAR at FPPF <= x and the ROC and DET charts come;
//   - the thesis's tables (with and without segmentation errors) and CLEAR MOT tracking figures at a list of
//     probability thresholds P(person) >= p, the tracker being rerun at each on the detections that pass;
//   - the classifier alone on the recording's candidates (those covering a counted person with IoU >= 0.5
//     are positives, those covering nobody negatives): AUC, and TAR / FAR at the operating probability,
//     the figures a model file's validation predicts;
//   - by clip (clip_bootstrap.hpp): each clip's figures at the operating probability, and TAR at FPPF <= 0.1
//     and 0.5 with a 95 % interval over clips, the spread from room to room that one over people hides.
// Thresholds are probabilities; a score threshold is h = calibration.score_at(p).
#include <memory>
#include <string>
#include <vector>

#include <optional>

#include "rdsf/classifier/platt_calibration.hpp"
#include "rdsf/classifier/training_record.hpp"
#include "rdsf/evaluation/clip_bootstrap.hpp"
#include "rdsf/evaluation/clear_mot.hpp"
#include "rdsf/evaluation/detection_metrics.hpp"
#include "rdsf/evaluation/ground_truth.hpp"
#include "rdsf/frame/camera_model.hpp"
#include "rdsf/tracking/tracker.hpp"

namespace rdsf {

/// What evaluation keeps of a frame: every candidate's box, depth, colour histogram and score.
struct EvaluatedCandidate {
  cv::Rect box;
  double depth_mm = 0;
  double score = 0;
  ColourHistogram histogram;
  CandidateKin kin;  ///< its object (kin_of(); default: related to none, never a duplicate)
};

struct EvaluatedFrame {
  std::string frame;  ///< name as in boxes.csv
  std::int64_t index = 0;
  CameraModel camera;
  std::vector<EvaluatedCandidate> candidates;
};

struct SweepRow {
  double probability = 0;  ///< P(person) >= this; all.threshold / clean.threshold hold the score threshold
  DetectionFigures all;    ///< every ground-truth person
  DetectionFigures clean;  ///< without segmentation errors
  MotFigures mot;
};

/// The classifier alone on the evaluated candidates.
struct CandidateFigures {
  long positives = 0, negatives = 0;  ///< candidates covering a counted person (IoU >= 0.5) / nobody
  double auc = 0;
  double tar = 0, far = 0;            ///< at the operating probability
  RateInterval tar_interval;          ///< tar's 95 % interval over `positives` (wilson_interval)
};

struct SweepResult {
  std::string model;             ///< label, e.g. "tree2 v3"
  std::vector<SweepRow> rows;    ///< one per probability threshold, in the given order
  SweepRow operating;            ///< at the operating probability
  double operating_probability = 0.5;
  std::vector<DetectionFigures> curve;  ///< exact, every distinct score, thresholds descending
  std::vector<double> curve_probability;  ///< P(person) of each curve threshold
  CandidateFigures candidates;
  /// The model file's validation at the operating probability (nearest kept level), when it has one.
  std::optional<ProbabilityPoint> validation;
  long segmentation_errors = 0;
  double fps = 0;                ///< whole-system frames per second measured while running it
  /// Row with the best MOTA among rows and the operating row (first of equals).
  const SweepRow& best_mota() const;
  /// Highest TAR on the exact curve with FPPF <= max_fppf; 0 when no point qualifies.
  double tar_at_fppf(double max_fppf) const;
  /// That TAR's 95 % interval over the people (wilson_interval of the people found at that point): how far
  /// the figure can move with other people of the same kind; the threshold's own variation (chosen on the
  /// same frames' false positives) is not in it. {0, 1} when no point qualifies.
  RateInterval tar_interval_at_fppf(double max_fppf) const;
  /// People with a candidate (IoU >= 0.5) over people.
  double candidate_recall() const;
  /// The frames per clip of numbered frames (clip_bootstrap.hpp).
  int clip_frames = 0;
  /// Each clip's figures at the operating probability, in order of their first frame.
  std::vector<ClipFigures> clips;
  /// TAR at FPPF <= 0.1 and <= 0.5: 95 % intervals over clips (ClipResampler::interval).
  ClipInterval clip_interval_01, clip_interval_05;
  /// The evaluated frames by clip, for differences between models paired over the same clips.
  std::shared_ptr<const ClipResampler> by_clip;
};

/// The default probability thresholds of the tables: 0.01, 0.02, 0.05, 0.10, ..., 0.95, 0.98, 0.99.
std::vector<double> default_probability_thresholds();

SweepResult sweep_thresholds(const std::vector<EvaluatedFrame>& frames, const GroundTruth& truth,
                             const std::vector<double>& probabilities, const TrackingParams& tracking,
                             const std::string& model_label, const ScoreCalibration& calibration,
                             double operating_probability, int clip_frames);

/// The files write_evaluation_report writes, as programs name them in --help and when done.
inline constexpr const char* kEvaluationReportFiles =
    "metrics.csv, curve.csv, clips.csv, outcomes.csv, summary.txt, summary.md, roc.png, det.png";

/// Writes metrics.csv (the tables), curve.csv (the exact curves), clips.csv (each clip at the operating
/// probability), outcomes.csv (each candidate's clip, score and outcome on the exact curve), summary.txt,
/// summary.md (one Markdown row per model), roc.png and det.png into `dir` (created when missing); returns
/// the summary text (also what summary.txt holds). With two or more models on the same frames, the summary
/// ends with each later model's TAR at FPPF <= 0.1 and 0.5 minus the first model's, with 95 % intervals
/// paired over clips (paired_difference).
std::string write_evaluation_report(const std::vector<SweepResult>& results, const std::string& dir);

}  // namespace rdsf
