#include "rdsf/labeling/track_propagation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/tracking/tracker.hpp"

namespace rdsf {
namespace {

struct Best {
  std::optional<std::size_t> index;  ///< the best candidate passing the gates
  bool sure = false;                 ///< the runner-up is at least ambiguity_margin lower
  std::vector<std::size_t> passing;  ///< every candidate passing the gates
};

Best best_match(const TrackCandidate& from, const std::vector<TrackCandidate>& in, char answer,
                const PropagationParams& params, const CameraModel& camera) {
  Best best;
  double best_iou = -1, runner_up = -1;
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (!passes_track_gates(from, in[i], answer, params, camera)) continue;
    best.passing.push_back(i);
    const double overlap = iou(from.box, in[i].box);
    if (overlap > best_iou) {
      runner_up = best_iou;
      best_iou = overlap;
      best.index = i;
    } else if (overlap > runner_up) {
      runner_up = overlap;
    }
  }
  // Candidates that fail the gates still make the link ambiguous when they overlap as much (a person beside
  // a crossing one whose depth or score differs is no reason to be sure).
  for (std::size_t i = 0; best.index && i < in.size(); ++i) {
    if (i == *best.index) continue;
    const double overlap = iou(from.box, in[i].box);
    if (overlap > runner_up) runner_up = overlap;
  }
  best.sure = best.index.has_value() && runner_up <= best_iou - params.ambiguity_margin;
  return best;
}

}  // namespace

bool passes_track_gates(const TrackCandidate& t, const TrackCandidate& c, char answer, const PropagationParams& params,
                        const CameraModel& camera) {
  if (params.within_image && c.cut_by_image) return false;
  if (iou(t.box, c.box) < params.min_iou) return false;
  if (std::abs(t.depth_mm - c.depth_mm) > params.max_depth_step_mm) return false;
  const double d_cm = cv::norm(centroid_cm(t.box, t.depth_mm, camera) - centroid_cm(c.box, c.depth_mm, camera));
  if (match_lkh({}, {}, d_cm) > params.max_lkh) return false;
  if (c.probability >= 0) {
    if (answer == 'y' && c.probability < params.min_yes_probability) return false;
    if (answer == 'n' && c.probability > params.max_no_probability) return false;
  }
  return true;
}

PropagatedTrack propagate_track(const std::vector<std::vector<TrackCandidate>>& frames, const TrackLink& seed,
                                char answer, const PropagationParams& params, const CameraModel& camera,
                                const AnswerOf& answer_of) {
  PropagatedTrack track;
  if (params.within_image && frames[seed.frame][seed.index].cut_by_image) return track;  // starts nowhere
  std::vector<TrackLink> backwards;
  for (const int step : {-1, 1}) {
    TrackLink at = seed;
    for (int followed = 0; params.max_frames <= 0 || followed < params.max_frames; ++followed) {
      if ((step < 0 && at.frame == 0) || (step > 0 && at.frame + 1 >= frames.size())) break;
      std::size_t next_frame = at.frame + step;
      const TrackCandidate& from = frames[at.frame][at.index];
      Best forward = best_match(from, frames[next_frame], answer, params, camera);
      // No candidate there passes the gates (the object's candidate missing, or failing a gate, in that frame):
      // up to max_gap_frames such frames are stepped over, to the next frame where one does.
      for (int gap = 1; gap <= params.max_gap_frames && forward.passing.empty(); ++gap) {
        const long later = static_cast<long>(next_frame) + step;
        if (later < 0 || later >= static_cast<long>(frames.size())) break;
        next_frame = static_cast<std::size_t>(later);
        forward = best_match(from, frames[next_frame], answer, params, camera);
      }
      bool sure = forward.sure;
      if (sure) {  // and back: t must be c's best among t's frame, as clearly
        const Best back = best_match(frames[next_frame][*forward.index], frames[at.frame], answer, params, camera);
        sure = back.sure && back.index == at.index;
      }
      if (!sure) {
        for (const std::size_t i : forward.passing) {
          const TrackLink link{next_frame, i};
          if (!answer_of || answer_of(link) == '\0') track.ask.push_back(link);
        }
        break;
      }
      const TrackLink next{next_frame, *forward.index};
      const char given = answer_of ? answer_of(next) : '\0';
      if (given != '\0' && given != answer) break;  // answered otherwise: the person knows better
      if (given == '\0') (step < 0 ? backwards : track.labelled).push_back(next);
      at = next;
    }
  }
  track.labelled.insert(track.labelled.begin(), backwards.rbegin(), backwards.rend());
  return track;
}

double depth_agreement(const cv::Mat1w& a, const cv::Mat1w& b, const cv::Rect& box, double max_change,
                       double min_valid_share) {
  if (a.size() != b.size() || box.area() <= 0) return -1;
  // Every step-th pixel in both directions, at most about 64 x 64 of them (a person's box is 90,000 pixels).
  const int step = std::max(1, static_cast<int>(std::ceil(std::sqrt(box.area() / 4096.0))));
  long sampled = 0, valid = 0, agreeing = 0;
  for (int y = box.y; y < box.br().y; y += step) {
    for (int x = box.x; x < box.br().x; x += step) {
      ++sampled;
      if (y < 0 || y >= a.rows || x < 0 || x >= a.cols) continue;  // outside the image: no reading
      const int da = a(y, x), db = b(y, x);
      if (da == 0 || db == 0) continue;
      ++valid;
      agreeing += std::abs(da - db) <= max_change * std::min(da, db) ? 1 : 0;
    }
  }
  if (valid == 0 || static_cast<double>(valid) < min_valid_share * static_cast<double>(sampled)) return -1;
  return static_cast<double>(agreeing) / static_cast<double>(valid);
}

std::vector<TrackLink> propagate_place(const std::vector<std::vector<TrackCandidate>>& frames,
                                       const std::vector<cv::Mat1w>& depth_mm, const TrackLink& seed, char answer,
                                       const PropagationParams& params, const AnswerOf& answer_of) {
  std::vector<TrackLink> labelled;
  if (!params.per_place || answer != 'n' || depth_mm.size() != frames.size()) return labelled;
  const TrackCandidate& s = frames[seed.frame][seed.index];
  const cv::Mat1w& seen = depth_mm[seed.frame];
  for (std::size_t g = 0; g < frames.size(); ++g) {
    if (g == seed.frame || depth_mm[g].empty() || depth_mm[g].size() != seen.size()) continue;
    std::optional<bool> same_view;  // computed once per frame, when a candidate needs it
    for (std::size_t i = 0; i < frames[g].size(); ++i) {
      const TrackCandidate& c = frames[g][i];
      if (iou(s.box, c.box) < params.place_min_iou) continue;
      if (std::abs(s.depth_mm - c.depth_mm) > params.place_max_depth_step_mm) continue;
      if (c.probability >= 0 && c.probability > params.max_no_probability) continue;
      if (answer_of && answer_of({g, i}) != '\0') continue;
      if (!same_view) {
        same_view = depth_agreement(seen, depth_mm[g], s.box, params.place_pixel_change, params.place_min_valid_share) >=
                    params.place_min_agreeing;
      }
      if (*same_view) labelled.push_back({g, i});
    }
  }
  return labelled;
}

namespace {

std::string answerer(const char* rule, const CandidateKey& seed) {
  char box[96];
  std::snprintf(box, sizeof box, " %d,%d,%d,%d", seed.box.x, seed.box.y, seed.box.width, seed.box.height);
  return rule + seed.frame + box;
}

}  // namespace

std::string track_answerer(const CandidateKey& seed) { return answerer("track ", seed); }

std::string place_answerer(const CandidateKey& seed) { return answerer("place ", seed); }

std::string model_track_answerer(const CandidateKey& seed) { return answerer("model-track ", seed); }

std::vector<JournalEntry> propagated_from(const AnswerJournal& journal, const CandidateKey& seed) {
  const std::string track = track_answerer(seed), place = place_answerer(seed);
  std::vector<JournalEntry> entries;
  for (const JournalEntry& e : journal.in_force()) {
    if ((e.by == track || e.by == place) && e.key.source == seed.source) entries.push_back(e);
  }
  return entries;
}

}  // namespace rdsf
