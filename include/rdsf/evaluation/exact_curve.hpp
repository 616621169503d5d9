#pragma once
// The exact detection curve: the thesis's figures (detection_metrics.hpp) at every distinct score, not at a
// fixed list of thresholds.
//
// Why one pass suffices: per frame the detections at threshold t are the candidates scoring >= t, matched
// highest score first. Lowering t only appends candidates to the end of that order, so every candidate's
// outcome (it detects a person, is a false positive, or is neither because it only covers a don't-care
// person) is the same at every threshold that admits it: the outcomes of the matching at the lowest
// threshold, cumulated in descending score order, give n_det and n_fp at every threshold. Duplicates
// (duplicate_candidates.hpp) are neutral: the rule is greedy by score too, so a candidate's being one does
// not depend on the threshold. A test checks it against detection_figures() at every distinct score.
#include <vector>

#include "rdsf/evaluation/detection_metrics.hpp"
#include "rdsf/evaluation/ground_truth.hpp"

namespace rdsf {

enum class CandidateOutcome { detection, false_positive, neutral };

/// Every candidate's outcome, per frame in candidate order, when all candidates are detections.
std::vector<std::vector<CandidateOutcome>> candidate_outcomes(const std::vector<FrameCandidates>& frames,
                                                              const GroundTruth& truth);

/// One point per distinct score, thresholds descending (the first point admits only the top-scoring
/// candidates, the last admits all). `without_segmentation_errors` leaves people without a candidate out of
/// n_people and n_miss, as detection_figures() does.
std::vector<DetectionFigures> exact_detection_curve(const std::vector<FrameCandidates>& frames,
                                                    const GroundTruth& truth, bool without_segmentation_errors);

}  // namespace rdsf
