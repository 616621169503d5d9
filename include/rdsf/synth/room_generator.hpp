#pragma once
// Random indoor rooms: ordinary rooms (the front wall at 2.5-5.5 m, in one room of five up to 8.5 m, side
// walls at 1.2-4 m from the camera), corridors (0.8-1.5 m to each side, 6-8.5 m deep) and open-plan offices
// and halls (2.5-5 m to each side, 5.5-8.5 m deep); windows, and furniture and clutter that is person-sized
// and not (tables, desks with monitors and their chairs, chairs, shelves, cupboards, stacked boxes and
// chairs, coat stands and coat racks with coats, plants, floor lamps, doors in their frames, partitions
// and walls at angles, bins and bags, robots), plus where the camera stands and how it moves (a mobile
// robot: 0.5-1.6 m high, a few degrees of pitch and roll, turned against the room so walls run at angles,
// driving slowly and rocking a little).
#include <algorithm>

#include "rdsf/synth/random.hpp"
#include "rdsf/synth/scene.hpp"

namespace rdsf::synth {

struct RoomParams {
  double front_min_m = 2.5, front_max_m = 5.5;  ///< distance of the front wall in most rooms
  double deep_room_share = 0.2;                 ///< share of deep rooms (halls, open spaces) ...
  double deep_front_max_m = 8.5;                ///< ... whose front wall is at front_max_m..deep_front_max_m
  double side_min_m = 1.2, side_max_m = 4.0;    ///< distance of each side wall from the camera axis
  int furniture_min = 5, furniture_max = 12;    ///< pieces of furniture (x1.6 open plan, x0.6 corridors)
  bool clutter = true;                          ///< desks, cupboards, plants, lamps, doors, coat racks...
  int clutter_min = 3, clutter_max = 9;         ///< extra clutter pieces (with clutter)
  /// Pieces of furniture and clutter moved 0.6-1.6 m in front of the camera, within 20 degrees of its heading:
  /// 1..this many a room (0: none, the default). A camera close to people is close to things too (a box, a
  /// desk, a chair back filling the image); docs/quality.md, "people-near".
  int near_clutter_max = 0;
  bool room_kinds = true;                       ///< corridors and open-plan offices besides rooms
  double corridor_share = 0.15, open_plan_share = 0.2;
  double floor_dropout_max = 0.1, wall_dropout_max = 0.02, furniture_dropout_max = 0.3;
  double camera_height_min_m = 0.5, camera_height_max_m = 1.6;
  double pitch_min_deg = -3.0, pitch_max_deg = 6.0;
  double roll_max_deg = 3.0;         ///< roll uniform in +-roll_max_deg
  double yaw_max_deg = 25.0;         ///< camera turned against the room (walls at angles)
  double camera_offset_max_m = 0.5;  ///< camera off the room's middle, sideways
  double moving_share = 0.5;         ///< share of clips in which the camera drives
  double camera_speed_max_mps = 0.4; ///< forward speed of a driving camera (-0.3..1 of it)
  double camera_turn_max_deg_s = 10; ///< turning rate of a driving camera
  double camera_wobble_deg = 0.4;    ///< pitch and roll rocking of a driving camera
};

/// A room and the camera pose in it, drawn from `rng`.
Room generate_room(Rng& rng, const RoomParams& params, CameraPose& camera);

/// How the camera moves during a clip: forward along its heading at forward_mps while turning at
/// yaw_rate_rad_s (an arc, kept inside the room), pitch and roll rocking by wobble_rad at wobble_hz.
struct CameraPath {
  CameraPose start;
  double forward_mps = 0, yaw_rate_rad_s = 0, wobble_rad = 0, wobble_hz = 0, wobble_phase = 0;
  double min_x = -1e9, max_x = 1e9, min_z = -1e9, max_z = 1e9;
  CameraPose at(double t_s) const;
};

/// The camera's path through `room` from `start` (standing still in 1 - moving_share of the clips).
CameraPath plan_camera_path(Rng& rng, const RoomParams& params, const Room& room, const CameraPose& start);

}  // namespace rdsf::synth
