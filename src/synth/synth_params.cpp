#include "rdsf/synth/synth_params.hpp"

#include <cstdio>

#include "rdsf/core/error.hpp"

namespace rdsf::synth {

SynthParams people_scene(int frames, int people_min, int people_max, std::uint64_t seed) {
  SynthParams p;
  p.frames = frames;
  p.people_min = people_min;
  p.people_max = people_max;
  p.seed = seed;
  return p;
}

CameraModel SynthParams::camera() const {
  if (fov_h_deg <= 0 && fov_v_deg <= 0) return CameraModel::kinect_v1().scaled_to(width_px, height_px);
  return CameraModel::from_field_of_view(width_px, height_px, fov_h_deg, fov_v_deg);
}

void SynthParams::validate() const {
  // each row of synth_parameters() checks the value it shows
  std::vector<std::pair<std::string, ParameterValue>> values;
  for (const Parameter<SynthParams>& row : synth_parameters()) values.emplace_back(row.name, row.get(*this));
  SynthParams checked = *this;
  set_synth_options(checked, values, /*classic=*/false);
  // what no row holds or what spans several rows
  if (!(room.furniture_min >= 0 && room.furniture_max <= 40 && room.furniture_min <= room.furniture_max)) {
    fail("--furniture " + std::to_string(room.furniture_min) + ".." + std::to_string(room.furniture_max),
         "must lie in 0..40 pieces with MIN <= MAX");
  }
  if (room.corridor_share + room.open_plan_share > 1.0) {
    char text[80];
    std::snprintf(text, sizeof text, "--corridors %g --open-plan %g", room.corridor_share, room.open_plan_share);
    fail(text, "the two shares add up to more than 1");
  }
}

}  // namespace rdsf::synth
