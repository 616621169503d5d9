#include "rdsf/candidates/foreground_candidates.hpp"

#include <algorithm>
#include <map>

namespace rdsf {

std::size_t add_foreground_candidates(const DepthFrame& frame, const Segmentation& in_front,
                                      const CandidateParams& params, cv::Size crop_size, CropColour colour,
                                      std::vector<Candidate>& candidates) {
  const std::size_t layer_candidates = candidates.size();
  int next_object = 0;
  for (const Candidate& c : candidates) next_object = std::max(next_object, c.object + 1);
  std::vector<Candidate> found = find_candidates(frame, in_front, params, crop_size, colour);
  std::map<int, int> own;  // an object of the foreground's own: its number among all the frame's objects
  for (Candidate& c : found) {
    double best = 0.0;
    const Candidate* nearest = nullptr;
    bool duplicate = false;
    for (std::size_t i = 0; i < layer_candidates; ++i) {
      const Candidate& other = candidates[i];
      if (other.layer != c.layer) continue;
      const double overlap = iou(c.strict_box, other.strict_box);
      duplicate = duplicate || (overlap >= kDuplicateIou && iou(c.fitted_box, other.fitted_box) >= kDuplicateIou);
      if (overlap > best) best = overlap, nearest = &other;
    }
    if (duplicate) continue;
    c.foreground = true;
    if (nearest != nullptr && best >= kPieceIou) {
      c.object = nearest->object;
      c.part = true;
    } else {
      const auto [at, added] = own.emplace(c.object, next_object);
      if (added) ++next_object;
      c.object = at->second;
    }
    candidates.push_back(std::move(c));
  }
  return candidates.size() - layer_candidates;
}

}  // namespace rdsf
