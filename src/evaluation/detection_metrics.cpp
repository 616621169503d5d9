#include "rdsf/evaluation/detection_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "rdsf/candidates/candidate_finder.hpp"

namespace rdsf {
namespace {

constexpr double kMinIou = 0.5;

}  // namespace

bool has_candidate(const FrameCandidates& frame, const cv::Rect& person) {
  return std::any_of(frame.candidates.begin(), frame.candidates.end(),
                     [&](const ScoredCandidate& c) { return iou(c.box, person) >= kMinIou; });
}

std::vector<char> duplicates_of(const FrameCandidates& frame) {
  std::vector<CandidateKin> kin;
  std::vector<double> scores;
  for (const ScoredCandidate& c : frame.candidates) {
    kin.push_back(c.kin);
    scores.push_back(c.score);
  }
  return duplicate_candidates(kin, scores);
}

std::vector<double> thesis_thresholds() { return {40, 20, 10, 0, -5, -10, -15, -20, -25, -30, -40, -60}; }

RateInterval wilson_interval(long successes, long trials, double z) {
  if (trials <= 0) return {};
  const double n = static_cast<double>(trials);
  const double p = static_cast<double>(successes) / n;
  const double z2 = z * z;
  const double denominator = 1.0 + z2 / n;
  const double centre = (p + z2 / (2.0 * n)) / denominator;
  const double half = z * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n)) / denominator;
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

void compute_rates(DetectionFigures& f) {
  f.tar = f.n_people > 0 ? static_cast<double>(f.n_det) / static_cast<double>(f.n_people) : 0.0;
  f.frr = f.n_people > 0 ? static_cast<double>(f.n_miss) / static_cast<double>(f.n_people) : 0.0;
  f.far = (f.n_fp + f.n_frames) > 0 ? static_cast<double>(f.n_fp) / static_cast<double>(f.n_fp + f.n_frames) : 0.0;
  f.trr = 1.0 - f.far;
  f.fppf = f.n_frames > 0 ? static_cast<double>(f.n_fp) / static_cast<double>(f.n_frames) : 0.0;
  f.mpf = f.n_frames > 0 ? static_cast<double>(f.n_miss) / static_cast<double>(f.n_frames) : 0.0;
}

long segmentation_errors(const std::vector<FrameCandidates>& frames, const GroundTruth& truth) {
  long errors = 0;
  for (const FrameCandidates& frame : frames) {
    for (const TruthBox& person : truth.in(frame.frame)) {
      if (!person.ignored) errors += has_candidate(frame, person.box) ? 0 : 1;
    }
  }
  return errors;
}

DetectionFigures detection_figures(const std::vector<FrameCandidates>& frames, const GroundTruth& truth,
                                   double threshold, bool without_segmentation_errors) {
  DetectionFigures f;
  f.threshold = threshold;
  for (const FrameCandidates& frame : frames) {
    ++f.n_frames;
    std::vector<cv::Rect> people, ignored;
    for (const TruthBox& person : truth.in(frame.frame)) {
      if (person.ignored) {
        ignored.push_back(person.box);
        continue;
      }
      if (without_segmentation_errors && !has_candidate(frame, person.box)) continue;
      people.push_back(person.box);
    }
    std::vector<const ScoredCandidate*> detections;
    const std::vector<char> duplicate = duplicates_of(frame);
    for (std::size_t i = 0; i < frame.candidates.size(); ++i) {
      if (frame.candidates[i].score >= threshold && duplicate[i] == 0) detections.push_back(&frame.candidates[i]);
    }
    std::stable_sort(detections.begin(), detections.end(),
                     [](const ScoredCandidate* a, const ScoredCandidate* b) { return a->score > b->score; });
    std::vector<bool> matched(people.size(), false);
    for (const ScoredCandidate* d : detections) {
      double best = kMinIou;
      int best_person = -1;
      for (std::size_t p = 0; p < people.size(); ++p) {
        const double overlap = iou(d->box, people[p]);
        if (!matched[p] && overlap >= best) {
          best = overlap;
          best_person = static_cast<int>(p);
        }
      }
      if (best_person < 0) {
        const bool of_ignored = std::any_of(ignored.begin(), ignored.end(),
                                            [&](const cv::Rect& box) { return iou(d->box, box) >= kMinIou; });
        if (!of_ignored) ++f.n_fp;  // a detection of a hardly visible person is neither right nor wrong
      } else {
        matched[static_cast<std::size_t>(best_person)] = true;
        ++f.n_det;
      }
    }
    f.n_people += static_cast<long>(people.size());
    f.n_miss += static_cast<long>(std::count(matched.begin(), matched.end(), false));
  }
  compute_rates(f);
  return f;
}

}  // namespace rdsf
