#pragma once
// Figures and intervals by clip. Consecutive frames show the same people in the same room, so the people of
// a recording are not independent trials: one room whose people never get a candidate misses in each of its
// frames, and an interval over person-frames (wilson_interval) is far narrower than the spread from room to
// room. A clip is a run of frames of one scene:
//   a frame whose name is a number n (recordings and synthetic sets): clip "#k" with k = n / clip_frames
//     (rdsf-synth renders a new room, camera and people every --clip-frames frames);
//   any other name: the name without its trailing run of digits, '-', '_' and '.' (lab_juggling2 ->
//     "lab_juggling", home_2013-10-05_15-46-03-286 -> "home"): one take of a named recording.
// The interval is a percentile bootstrap over clips: `resamples` draws of as many clips as there are, with
// replacement, each giving TAR at FPPF <= x of the exact curve (exact_curve.hpp) of the drawn clips' frames
// (a clip drawn twice counts twice); the 2.5 % and 97.5 % quantiles of the draws. A draw whose clips hold
// nobody who counts (clips of empty rooms, or of people less than --min-visible visible) has no TAR and is
// left out; when every draw is such, there is no interval. The draws come from a
// fixed seed (std::mt19937_64, defined by the standard), so the interval is the same on every machine and
// thread count. With fewer than two clips there is no interval (a single recording says nothing about how
// other rooms would do); with fewer than kFewClips the bootstrap can only recombine the few clips it has and
// comes out too narrow (the real lab's 5 takes: 0.90-1.00 where Wilson's over its 27 people is 0.77-0.98), so
// reports flag it and the wider interval is the one to read.
#include <cstdint>
#include <string>
#include <vector>

#include "rdsf/evaluation/detection_metrics.hpp"
#include "rdsf/evaluation/ground_truth.hpp"

namespace rdsf {

/// The clip of `frame` as above; clip_frames >= 1 (else Error).
std::string clip_of(const std::string& frame, int clip_frames);

/// One clip's figures at one score threshold (the operating point).
struct ClipFigures {
  std::string clip;
  long frames = 0;
  long people = 0;          ///< counted (not ignored) people over its frames
  long with_candidate = 0;  ///< of them, covered by a candidate with IoU >= 0.5
  long detected = 0;        ///< of them, detected at the threshold
  long false_positives = 0;
};

/// Below this many clips an interval over clips understates the spread (see above).
constexpr int kFewClips = 10;

/// A bootstrap interval over clips; `clips` < 2: none (interval {0, 1}).
struct ClipInterval {
  int clips = 0;
  RateInterval interval;
  bool known() const { return clips >= 2; }
  bool few() const { return clips < kFewClips; }
};

class ClipResampler {
 public:
  /// The frames' candidates (scored) against `truth`, frames grouped by clip_of(frame, clip_frames).
  ClipResampler(const std::vector<FrameCandidates>& frames, const GroundTruth& truth, int clip_frames);

  int clips() const { return static_cast<int>(clips_.size()); }
  /// Clip names in order of their first frame.
  const std::vector<std::string>& names() const { return names_; }
  /// Counted people per clip, in names() order.
  std::vector<long> people_per_clip() const;

  /// TAR at FPPF <= max_fppf of the exact curve with clip c counted weights[c] times (weights all 1: the
  /// recording's own figure, SweepResult::tar_at_fppf). 0 when no point qualifies or nobody is counted.
  double tar_at_fppf(const std::vector<int>& weights, double max_fppf) const;

  /// The percentile bootstrap interval of tar_at_fppf over clips (see above).
  ClipInterval interval(double max_fppf, int resamples = 2000, std::uint64_t seed = 1) const;

  /// Each clip's figures at `score_threshold`, in names() order.
  std::vector<ClipFigures> figures(double score_threshold) const;

  /// A candidate's score, clip (index into names()) and outcome on the exact curve.
  struct Outcome {
    double score;
    int clip;
    std::int8_t kind;  ///< 1 detection, -1 false positive, 0 neutral (exact_curve.hpp's CandidateOutcome)
  };
  /// Every candidate of every frame, score descending (stable: frame order within a score).
  const std::vector<Outcome>& outcomes() const { return outcomes_; }

 private:
  struct Clip {
    long frames = 0, people = 0, with_candidate = 0;
  };
  std::vector<Outcome> outcomes_;  // every candidate, score descending (stable)
  std::vector<Clip> clips_;
  std::vector<std::string> names_;
};

/// Model b against model a on the same frames: b's TAR at FPPF <= max_fppf minus a's, and its 95 % interval
/// over clips from draws that weigh each clip alike for both (a paired bootstrap: the rooms both find hard
/// cancel, so a difference is pinned far more tightly than either figure). a and b must hold the same clips
/// in the same order (else Error); the draws are interval()'s, with the same seed.
struct ClipDifference {
  double difference = 0;
  ClipInterval interval;  ///< of the difference; {0, 1} unknown (fewer than two clips)
};
ClipDifference paired_difference(const ClipResampler& a, const ClipResampler& b, double max_fppf,
                                 int resamples = 2000, std::uint64_t seed = 1);

}  // namespace rdsf
