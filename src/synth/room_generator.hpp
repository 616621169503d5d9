#pragma once
// Random indoor rooms: the front wall at 2.5-5.5 m (in one room of five up to 8.5 m), side walls at
// 1.2-4 m from the camera axis, windows, and furniture that is person-sized but not a person (tables, chairs,
// shelves, stacked boxes, a coat stand, a robot-like column, cabinets with a screen), plus where the camera
// stands.
#include "synth/random.hpp"
#include "synth/scene.hpp"

namespace rdsf::synth {

struct RoomParams {
  double front_min_m = 2.5, front_max_m = 5.5;  ///< distance of the front wall in most rooms
  double deep_room_share = 0.2;                 ///< share of deep rooms (halls, open spaces) ...
  double deep_front_max_m = 8.5;                ///< ... whose front wall is at front_max_m..deep_front_max_m
  double side_min_m = 1.2, side_max_m = 4.0;    ///< distance of each side wall from the camera axis
  int furniture_min = 5, furniture_max = 12;    ///< pieces of furniture
  double camera_height_min_m = 0.7, camera_height_max_m = 1.2;
  double pitch_min_deg = -3.0, pitch_max_deg = 6.0;
};

/// A room and the camera pose in it, drawn from `rng`.
Room generate_room(Rng& rng, const RoomParams& params, CameraPose& camera);

}  // namespace rdsf::synth
