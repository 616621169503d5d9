#include "rdsf/evaluation/clear_mot.hpp"

#include <algorithm>
#include <tuple>

#include "rdsf/candidates/candidate_finder.hpp"

namespace rdsf {

void ClearMot::add_frame(const std::vector<TrackedBox>& truth, const std::vector<TrackedBox>& hypotheses) {
  constexpr double kMinIou = 0.5;
  std::vector<bool> truth_done(truth.size(), false), hypothesis_done(hypotheses.size(), false);
  std::map<int, int> current;
  auto match = [&](std::size_t t, std::size_t h, double overlap) {
    truth_done[t] = hypothesis_done[h] = true;
    ++figures_.matches;
    figures_.iou_sum += overlap;
    const int track = truth[t].id, id = hypotheses[h].id;
    const auto last = last_.find(track);
    if (last != last_.end() && last->second != id) ++figures_.mismatches;
    last_[track] = id;
    current[track] = id;
  };
  // 1. Keep last frame's correspondences that still hold.
  for (std::size_t t = 0; t < truth.size(); ++t) {
    const auto previous = previous_.find(truth[t].id);
    if (previous == previous_.end()) continue;
    for (std::size_t h = 0; h < hypotheses.size(); ++h) {
      if (hypothesis_done[h] || hypotheses[h].id != previous->second) continue;
      const double overlap = iou(truth[t].box, hypotheses[h].box);
      if (overlap >= kMinIou) match(t, h, overlap);
      break;
    }
  }
  // 2. The rest, largest overlap first.
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  for (std::size_t t = 0; t < truth.size(); ++t) {
    for (std::size_t h = 0; h < hypotheses.size(); ++h) {
      if (truth_done[t] || hypothesis_done[h]) continue;
      const double overlap = iou(truth[t].box, hypotheses[h].box);
      if (overlap >= kMinIou) pairs.emplace_back(-overlap, t, h);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  for (const auto& [negative_overlap, t, h] : pairs) {
    if (!truth_done[t] && !hypothesis_done[h]) match(t, h, -negative_overlap);
  }
  figures_.truth += static_cast<long>(truth.size());
  figures_.misses += static_cast<long>(std::count(truth_done.begin(), truth_done.end(), false));
  figures_.false_positives += static_cast<long>(std::count(hypothesis_done.begin(), hypothesis_done.end(), false));
  previous_ = current;
}

}  // namespace rdsf
