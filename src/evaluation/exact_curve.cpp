#include "rdsf/evaluation/exact_curve.hpp"

#include <algorithm>
#include <numeric>

#include "rdsf/candidates/candidate_finder.hpp"

namespace rdsf {
namespace {

constexpr double kMinIou = 0.5;

}  // namespace

std::vector<std::vector<CandidateOutcome>> candidate_outcomes(const std::vector<FrameCandidates>& frames,
                                                              const GroundTruth& truth) {
  std::vector<std::vector<CandidateOutcome>> out;
  for (const FrameCandidates& frame : frames) {
    std::vector<cv::Rect> people, ignored;
    for (const TruthBox& person : truth.in(frame.frame)) (person.ignored ? ignored : people).push_back(person.box);
    std::vector<std::size_t> order(frame.candidates.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return frame.candidates[a].score > frame.candidates[b].score;
    });
    std::vector<CandidateOutcome> outcome(frame.candidates.size(), CandidateOutcome::neutral);
    std::vector<bool> matched(people.size(), false);
    const std::vector<char> duplicate = duplicates_of(frame);
    for (std::size_t i : order) {
      if (duplicate[i] != 0) continue;  // no detection at any threshold: neutral
      const cv::Rect& box = frame.candidates[i].box;
      double best = kMinIou;
      int best_person = -1;
      for (std::size_t p = 0; p < people.size(); ++p) {
        const double overlap = iou(box, people[p]);
        if (!matched[p] && overlap >= best) {
          best = overlap;
          best_person = static_cast<int>(p);
        }
      }
      if (best_person >= 0) {
        matched[static_cast<std::size_t>(best_person)] = true;
        outcome[i] = CandidateOutcome::detection;
      } else if (std::none_of(ignored.begin(), ignored.end(), [&](const cv::Rect& b) { return iou(box, b) >= kMinIou; })) {
        outcome[i] = CandidateOutcome::false_positive;
      }
    }
    out.push_back(std::move(outcome));
  }
  return out;
}

std::vector<DetectionFigures> exact_detection_curve(const std::vector<FrameCandidates>& frames,
                                                    const GroundTruth& truth, bool without_segmentation_errors) {
  const std::vector<std::vector<CandidateOutcome>> outcomes = candidate_outcomes(frames, truth);
  struct Scored {
    double score;
    CandidateOutcome outcome;
  };
  std::vector<Scored> all;
  long people = 0;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    for (std::size_t i = 0; i < frames[f].candidates.size(); ++i) all.push_back({frames[f].candidates[i].score, outcomes[f][i]});
    for (const TruthBox& person : truth.in(frames[f].frame)) {
      if (person.ignored) continue;
      const bool covered = std::any_of(frames[f].candidates.begin(), frames[f].candidates.end(),
                                       [&](const ScoredCandidate& c) { return iou(c.box, person.box) >= kMinIou; });
      if (!without_segmentation_errors || covered) ++people;
    }
  }
  std::stable_sort(all.begin(), all.end(), [](const Scored& a, const Scored& b) { return a.score > b.score; });
  std::vector<DetectionFigures> curve;
  DetectionFigures f;
  f.n_frames = static_cast<long>(frames.size());
  f.n_people = people;
  for (std::size_t k = 0; k < all.size(); ++k) {
    if (all[k].outcome == CandidateOutcome::detection) ++f.n_det;
    if (all[k].outcome == CandidateOutcome::false_positive) ++f.n_fp;
    if (k + 1 < all.size() && all[k + 1].score == all[k].score) continue;  // one point per distinct score
    f.threshold = all[k].score;
    f.n_miss = f.n_people - f.n_det;
    compute_rates(f);
    curve.push_back(f);
  }
  return curve;
}

}  // namespace rdsf
