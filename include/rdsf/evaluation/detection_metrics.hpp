#pragma once
// The thesis's detection figures for one classifier threshold, from every candidate's score and the ground
// truth. Per frame, the candidates scoring >= threshold are the detections; taken highest score first, each
// is matched to the not yet matched ground-truth person it overlaps most (strict box against truth box,
// IoU >= 0.5). A detection left without a person is a false positive, so duplicates of one person count as
// false positives except one; a person left without a detection is a miss.
//
// Definitions (as in the thesis's tables):
//   TAR = n_det / n_people          FRR = n_miss / n_people = 1 - TAR
//   FAR = n_fp / (n_fp + n_frames)  TRR = 1 - FAR   (the tables count one true negative per frame)
//   FPPF = n_fp / n_frames          MPF = n_miss / n_frames
// e.g. n_fp = 33 over 608 frames gives FAR = 33 / 641 = 0.051482 (thesis, tree2 at threshold 0). The
// thesis's text misprints n_miss; the tables' definitions are the ones implemented.
//
// People marked ignored (hardly visible, see ignore_hardly_visible()) count neither as misses nor as
// people, and a detection of one counts neither as a detection nor as a false positive.
//
// Duplicates (duplicate_candidates.hpp: a whole object and a piece of it, the lower-scoring one) are no
// detections at any threshold; they still count as candidates for segmentation errors.
//
// "Without segmentation errors": a person no candidate overlaps with IoU >= 0.5 was never shown to the
// classifier; that table leaves such people out of n_people and n_miss.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/candidates/duplicate_candidates.hpp"
#include "rdsf/evaluation/ground_truth.hpp"

namespace rdsf {

struct ScoredCandidate {
  cv::Rect box;  ///< the reported box
  double score = 0;
  CandidateKin kin;  ///< its object: a duplicate of a higher-scoring one is no detection (duplicate_candidates.hpp)
};


struct FrameCandidates {
  std::string frame;                       ///< name, as in boxes.csv
  std::vector<ScoredCandidate> candidates; ///< every candidate of the frame, with its score
};

/// Per candidate of the frame, 1 when it is a duplicate (duplicate_candidates()) and so never a detection.
std::vector<char> duplicates_of(const FrameCandidates& frame);

struct DetectionFigures {
  double threshold = 0;
  long n_frames = 0, n_people = 0, n_det = 0, n_fp = 0, n_miss = 0;
  double tar = 0, far = 0, trr = 0, frr = 0, fppf = 0, mpf = 0;
};

/// Figures at one threshold over all frames (frames missing from `truth` have no people).
DetectionFigures detection_figures(const std::vector<FrameCandidates>& frames, const GroundTruth& truth,
                                   double threshold, bool without_segmentation_errors = false);

/// Whether a candidate of `frame` overlaps `person` with IoU >= 0.5 (else a segmentation error).
bool has_candidate(const FrameCandidates& frame, const cv::Rect& person);

/// Number of people no candidate overlaps with IoU >= 0.5 (segmentation errors).
long segmentation_errors(const std::vector<FrameCandidates>& frames, const GroundTruth& truth);

/// Fills the rates from the counts.
void compute_rates(DetectionFigures& f);

/// A rate's 95 % interval (Wilson score interval, z = 1.96) from `successes` of `trials`:
///   centre = (p + z^2 / 2n) / (1 + z^2 / n), half width = z sqrt(p (1 - p) / n + z^2 / 4n^2) / (1 + z^2 / n),
/// with p = successes / n; it stays in [0, 1] and is wide where n is small (49 people: about +-0.11 at 0.75).
/// {0, 1} when trials is 0.
struct RateInterval {
  double low = 0, high = 1;
};
RateInterval wilson_interval(long successes, long trials, double z = 1.96);

/// The thesis's sweep of threshold_classifier.
std::vector<double> thesis_thresholds();

}  // namespace rdsf
