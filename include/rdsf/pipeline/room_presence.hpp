#pragma once
// Where a room recording has nobody in it, as far as a model and the tracker can tell (rdsf-adapt's room
// negatives without a people-free recording), and whether a recording said to be empty has people in it.
//
// Every frame is run through the whole system (PeoplePipeline) with the detection threshold lowered to
// sighting_probability: a frame has a sighting when a candidate reaches it. A frame is taken as empty
// when no frame within margin_frames before or after it (itself included) has a sighting, and it lies in
// a run of at least min_stretch_frames such frames. Lower thresholds and wider margins trade fewer people
// taken as empty for fewer empty frames (measured: docs/adapting-to-your-room.md).
// A person is "confidently tracked" over the frames in which the tracker matched them with a detection of
// P(person) >= confident_probability; the longest such count says a recording is not empty
// (confident_track_frames and more). 0.7, not 0.9: the shipped people/v2 gives a person standing at 1.5 m in a
// synthetic room P 0.75-0.85; a people-free recording whose strongest false positive reaches 0.7 in 5 frames
// is refused too (the message names the frame: look, and mine it without --empty's check by not giving it).
// Both probabilities are for a model read at P >= 0.5. For a model that states another operating point op
// (operating_point.hpp) they keep their log-odds from it: odds(P') = odds(P) odds(op) (RoomPresence::rule);
// people/v3 (op 0.27) gives a close person a lower P than v2, as it gives every person.
#include <string>
#include <vector>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"

namespace rdsf {

struct PresenceParams {
  double sighting_probability = 0.2;
  int margin_frames = 15;
  int min_stretch_frames = 10;
  double confident_probability = 0.7;
  int confident_track_frames = 5;
};

struct RoomPresence {
  PresenceParams rule;              ///< the rule as applied: its probabilities at the model's operating point
  std::vector<std::string> frames;  ///< frame names, in order
  std::vector<char> sighting;       ///< per frame: a candidate with P >= sighting_probability
  std::vector<char> empty;          ///< per frame: taken as people-free (the rule above)
  int longest_confident_track = 0;  ///< frames of the most confidently tracked person
  std::string confident_track_end;  ///< the frame where that person was last matched
  std::size_t empty_frames() const;
};

/// Scans `source` (a frame source spec) with `model` (which must outlive the call).
RoomPresence scan_room_presence(const std::string& source, const BoostedModel& model, const PipelineParams& pipeline,
                                const CameraModel& camera, const PresenceParams& params = {});

}  // namespace rdsf
