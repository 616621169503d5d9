#pragma once
// Where the people of one clip are in every frame: each walks on a smooth path between free spots of the
// room (turning gradually, around furniture, in and out of the camera's view) and stands still for a
// while in between, facing any way (front, back, side), doing something with their arms or bending down.
// Some walk and stand beside the person planned before them (pairs and groups), some sit on a free chair
// of the room for the whole clip. The gait phase advances with the distance walked.
#include <vector>

#include "rdsf/synth/person_model.hpp"
#include "rdsf/synth/random.hpp"
#include "rdsf/synth/scene.hpp"

namespace rdsf::synth {

struct PeopleParams {
  double speed_min_mps = 0.7, speed_max_mps = 1.5;  ///< walking speed
  double stride_m = 1.35;                           ///< distance of one gait cycle (two steps) at 1.75 m
  double nearest_m = 1.6, farthest_m = 7.0;         ///< distance range (Z) the paths stay in
  /// Paths keep this far from walls and furniture (metres; a body's half-width is about 0.2 m).
  double clearance_m = 0.5;
  double in_view_share = 0.8;  ///< share of spots drawn in the camera's view (the rest anywhere in the room)
  double frame_interval_s = 1.0 / 30.0;
  /// Share of walks that head mostly towards or away from the camera (the rest go anywhere).
  double along_room_share = 0.75;
  BodyParams body;            ///< bodies and outfits
  bool poses = true;          ///< sitting, bending, arms raised, out, crossed, in pockets, pointing, waving
  double sitting_share = 0.2; ///< chance that a person sits on a free chair (with poses)
  double group_share = 0.3;   ///< chance that a person walks and stands beside the one planned before
};

struct PersonTrack {
  int track = 0;
  PersonBody body;
  std::vector<PersonPose> poses;  ///< one per frame of the clip
};

/// Plans `count` people over `frames` frames in `room`, with track ids first_track, first_track+1, ...
/// Most of the spots people walk between are in the view of `camera` (its pose at the start of the clip).
std::vector<PersonTrack> plan_people(Rng& rng, const Room& room, int count, int frames, int first_track,
                                     const PeopleParams& params = {}, const CameraPose& camera = {});

}  // namespace rdsf::synth
