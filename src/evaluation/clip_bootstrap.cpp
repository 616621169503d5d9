#include "rdsf/evaluation/clip_bootstrap.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "rdsf/core/error.hpp"
#include "rdsf/evaluation/exact_curve.hpp"

namespace rdsf {

std::string clip_of(const std::string& frame, int clip_frames) {
  if (clip_frames < 1) throw Error("clip_of: clip_frames must be at least 1, got " + std::to_string(clip_frames));
  const bool number = !frame.empty() && frame.size() <= 18 &&
                      std::all_of(frame.begin(), frame.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (number) return "#" + std::to_string(std::stoll(frame) / clip_frames);
  std::size_t end = frame.size();
  while (end > 0) {
    const char c = frame[end - 1];
    if (!((c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.')) break;
    --end;
  }
  return end > 0 ? frame.substr(0, end) : frame;
}

ClipResampler::ClipResampler(const std::vector<FrameCandidates>& frames, const GroundTruth& truth,
                             int clip_frames) {
  std::map<std::string, int> index;
  const std::vector<std::vector<CandidateOutcome>> outcome = candidate_outcomes(frames, truth);
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const std::string name = clip_of(frames[f].frame, clip_frames);
    const auto [at, added] = index.emplace(name, static_cast<int>(names_.size()));
    if (added) {
      names_.push_back(name);
      clips_.emplace_back();
    }
    const int c = at->second;
    Clip& clip = clips_[static_cast<std::size_t>(c)];
    ++clip.frames;
    for (const TruthBox& person : truth.in(frames[f].frame)) {
      if (person.ignored) continue;
      ++clip.people;
      if (has_candidate(frames[f], person.box)) ++clip.with_candidate;
    }
    for (std::size_t i = 0; i < frames[f].candidates.size(); ++i) {
      const CandidateOutcome o = outcome[f][i];
      const std::int8_t kind = o == CandidateOutcome::detection ? 1 : (o == CandidateOutcome::false_positive ? -1 : 0);
      outcomes_.push_back({frames[f].candidates[i].score, c, kind});
    }
  }
  std::stable_sort(outcomes_.begin(), outcomes_.end(), [](const Outcome& a, const Outcome& b) { return a.score > b.score; });
}

double ClipResampler::tar_at_fppf(const std::vector<int>& weights, double max_fppf) const {
  long frames = 0, people = 0;
  for (std::size_t c = 0; c < clips_.size(); ++c) {
    frames += weights[c] * clips_[c].frames;
    people += weights[c] * clips_[c].people;
  }
  if (frames == 0 || people == 0) return 0.0;
  // The exact curve's points are the ends of runs of equal scores; n_fp only grows along it, so the last
  // point within max_fppf has the highest TAR of those that are.
  long det = 0, fp = 0;
  double best = 0.0;
  for (std::size_t k = 0; k < outcomes_.size(); ++k) {
    const long w = weights[static_cast<std::size_t>(outcomes_[k].clip)];
    if (outcomes_[k].kind > 0) det += w;
    if (outcomes_[k].kind < 0) fp += w;
    if (k + 1 < outcomes_.size() && outcomes_[k + 1].score == outcomes_[k].score) continue;
    if (static_cast<double>(fp) / static_cast<double>(frames) > max_fppf) break;
    best = static_cast<double>(det) / static_cast<double>(people);
  }
  return best;
}

namespace {

// The percentile bootstrap over clips shared by interval() and paired_difference(): `resamples` draws of as
// many clips as there are, with replacement, from std::mt19937_64(seed); a draw whose clips hold nobody is
// left out; `statistic(weights)` of each other draw; its 2.5 % and 97.5 % quantiles.
template <class Statistic>
ClipInterval bootstrap(const std::vector<long>& people, int resamples, std::uint64_t seed, Statistic statistic) {
  ClipInterval out;
  out.clips = static_cast<int>(people.size());
  if (out.clips < 2 || resamples < 1) return out;
  std::mt19937_64 random(seed);
  const std::uint64_t n = people.size();
  std::vector<int> weights(people.size());
  std::vector<double> draws;
  draws.reserve(static_cast<std::size_t>(resamples));
  for (int r = 0; r < resamples; ++r) {
    std::fill(weights.begin(), weights.end(), 0);
    long drawn = 0;
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::size_t c = static_cast<std::size_t>(random() % n);
      ++weights[c];
      drawn += people[c];
    }
    if (drawn > 0) draws.push_back(statistic(weights));  // a draw of nobody has no TAR
  }
  if (draws.empty()) {
    out.clips = 0;
    return out;
  }
  std::sort(draws.begin(), draws.end());
  const auto at = [&](double q) {
    const double position = q * static_cast<double>(draws.size() - 1);
    return draws[static_cast<std::size_t>(std::lround(position))];
  };
  out.interval = {at(0.025), at(0.975)};
  return out;
}

}  // namespace

std::vector<long> ClipResampler::people_per_clip() const {
  std::vector<long> people;
  for (const Clip& c : clips_) people.push_back(c.people);
  return people;
}

ClipInterval ClipResampler::interval(double max_fppf, int resamples, std::uint64_t seed) const {
  return bootstrap(people_per_clip(), resamples, seed,
                   [&](const std::vector<int>& weights) { return tar_at_fppf(weights, max_fppf); });
}

ClipDifference paired_difference(const ClipResampler& a, const ClipResampler& b, double max_fppf, int resamples,
                                 std::uint64_t seed) {
  if (a.names() != b.names() || a.people_per_clip() != b.people_per_clip()) {
    throw Error("paired_difference: the two evaluations do not hold the same clips");
  }
  ClipDifference out;
  const std::vector<int> all(a.names().size(), 1);
  out.difference = b.tar_at_fppf(all, max_fppf) - a.tar_at_fppf(all, max_fppf);
  out.interval = bootstrap(a.people_per_clip(), resamples, seed, [&](const std::vector<int>& weights) {
    return b.tar_at_fppf(weights, max_fppf) - a.tar_at_fppf(weights, max_fppf);
  });
  return out;
}

std::vector<ClipFigures> ClipResampler::figures(double score_threshold) const {
  std::vector<ClipFigures> out(clips_.size());
  for (std::size_t c = 0; c < clips_.size(); ++c) {
    out[c].clip = names_[c];
    out[c].frames = clips_[c].frames;
    out[c].people = clips_[c].people;
    out[c].with_candidate = clips_[c].with_candidate;
  }
  for (const Outcome& o : outcomes_) {
    if (o.score < score_threshold) break;
    if (o.kind > 0) ++out[static_cast<std::size_t>(o.clip)].detected;
    if (o.kind < 0) ++out[static_cast<std::size_t>(o.clip)].false_positives;
  }
  return out;
}

}  // namespace rdsf
