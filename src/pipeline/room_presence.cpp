#include "rdsf/pipeline/room_presence.hpp"

#include <algorithm>
#include <map>

#include "rdsf/frame/frame_source.hpp"

namespace rdsf {

std::size_t RoomPresence::empty_frames() const {
  return static_cast<std::size_t>(std::count(empty.begin(), empty.end(), 1));
}

namespace {

// `probability` for a model read at P >= 0.5, for `model`: the same log-odds from its operating point.
double at_operating_point(double probability, const BoostedModel& model) {
  if (!model.operating_point()) return probability;
  const double op = model.operating_probability();
  const double odds = probability / (1.0 - probability) * op / (1.0 - op);
  return odds / (1.0 + odds);
}

// `params` for `model`: its probabilities moved to the model's operating point; unchanged for a model that
// states none.
PresenceParams presence_params_for(const BoostedModel& model, const PresenceParams& params) {
  PresenceParams moved = params;
  moved.sighting_probability = at_operating_point(params.sighting_probability, model);
  moved.confident_probability = at_operating_point(params.confident_probability, model);
  return moved;
}

}  // namespace

RoomPresence scan_room_presence(const std::string& source, const BoostedModel& model, const PipelineParams& pipeline,
                                const CameraModel& camera, const PresenceParams& given) {
  const PresenceParams params = presence_params_for(model, given);
  PipelineParams p = pipeline;
  p.probability_threshold = params.sighting_probability;
  PeoplePipeline system(p, &model);
  RoomPresence presence;
  presence.rule = params;
  std::map<int, int> confident;  // person id -> frames matched with P >= confident_probability
  const auto frames = open_frame_source(source, camera);
  DepthFrame frame;
  while (frames->next(frame)) {
    const PipelineFrame result = system.process(frame);
    bool seen = false;
    for (std::size_t i = 0; i < result.probabilities.size(); ++i) {
      seen = seen || result.probabilities[i] >= params.sighting_probability;
      if (result.person[i] != 0 && result.probabilities[i] >= params.confident_probability) {
        const int n = ++confident[result.person[i]];
        if (n > presence.longest_confident_track) {
          presence.longest_confident_track = n;
          presence.confident_track_end = frame.name;
        }
      }
    }
    presence.frames.push_back(frame.name);
    presence.sighting.push_back(seen ? 1 : 0);
  }
  // Empty: no sighting within margin_frames either side, in a run of at least min_stretch_frames.
  const auto n = static_cast<long>(presence.frames.size());
  std::vector<char> clear(presence.frames.size(), 0);
  for (long f = 0; f < n; ++f) {
    bool any = false;
    for (long g = std::max(0L, f - params.margin_frames); g <= std::min(n - 1, f + params.margin_frames) && !any; ++g) {
      any = presence.sighting[static_cast<std::size_t>(g)] != 0;
    }
    clear[static_cast<std::size_t>(f)] = any ? 0 : 1;
  }
  presence.empty.assign(clear.size(), 0);
  for (long f = 0; f < n;) {
    long end = f;
    while (end < n && clear[static_cast<std::size_t>(end)] != 0) ++end;
    if (end - f >= params.min_stretch_frames) {
      std::fill(presence.empty.begin() + f, presence.empty.begin() + end, 1);
    }
    f = std::max(end, f + 1);
  }
  return presence;
}

}  // namespace rdsf
