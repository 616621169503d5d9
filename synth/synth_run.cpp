#include "synth/synth_run.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "rdsf/core/error.hpp"

#include "cli/progress.hpp"
#include "rdsf/synth/synth_sequence.hpp"
#include "rdsf/synth/synth_writer.hpp"

namespace rdsf {

int run_synth(SynthOptions o) {
  synth::parse_people_range(o.people, o.params.people_min, o.params.people_max);
  synth::parse_image_size(o.size, o.params.width_px, o.params.height_px);
  synth::parse_field_of_view(o.fov, o.params.fov_h_deg, o.params.fov_v_deg);
  synth::SynthParams& p = o.params;
  synth::parse_real_range("--camera-height", o.camera_height, p.room.camera_height_min_m, p.room.camera_height_max_m);
  synth::parse_real_range("--camera-pitch", o.camera_pitch, p.room.pitch_min_deg, p.room.pitch_max_deg);
  synth::parse_real_range("--people-distance", o.people_distance, p.people.nearest_m, p.people.farthest_m);
  double clutter_min = 0, clutter_max = 0;
  synth::parse_real_range("--clutter", o.clutter, clutter_min, clutter_max);
  if (clutter_min != std::floor(clutter_min) || clutter_max != std::floor(clutter_max)) {
    fail("--clutter " + o.clutter, "expected whole numbers of pieces");
  }
  p.room.clutter_min = static_cast<int>(std::max(-1.0, std::min(clutter_min, 1000.0)));
  p.room.clutter_max = static_cast<int>(std::max(-1.0, std::min(clutter_max, 1000.0)));
  p.room.clutter = p.room.clutter_max > 0;
  synth::parse_real_range("--eight-bit-step", o.eight_bit_step, p.sensor.eight_bit_step_min_mm,
                          p.sensor.eight_bit_step_max_mm);
  p.people.body.outfits = synth::parse_on_off("--outfits", o.outfits);
  p.people.poses = synth::parse_on_off("--poses", o.poses);
  p.people.body.varied_bodies = synth::parse_on_off("--bodies", o.bodies);
  p.room.room_kinds = synth::parse_on_off("--room-kinds", o.room_kinds);
  if (o.classic) p.set_classic();
  o.params.validate();
  synth::SynthSequence sequence(o.params);  // validated before anything touches the folder
  synth::prepare_output_folder(o.out_dir, o.force);
  synth::SynthWriter writer(o.out_dir, o.params, o.force);
  std::cerr << "rdsf-synth: " << o.params.frames << " frames " << o.params.width_px << "x"
            << o.params.height_px << (o.params.empty ? ", no people" : ", people " + o.people) << ", seed "
            << o.params.seed << " -> " << o.out_dir << "\n";
  cli::Progress progress(std::cerr, "frames", o.params.frames);
  long long boxes = 0;
  for (int i = 0; i < o.params.frames; ++i) {
    const synth::SynthFrame frame = sequence.frame(i);
    writer.write(frame);
    boxes += static_cast<long long>(frame.people.size());
    progress.update(i + 1, "boxes " + std::to_string(boxes));
  }
  progress.finish(o.params.frames, "boxes " + std::to_string(boxes));
  writer.commit(o.command_line);
  std::cerr << "rdsf-synth: wrote " << o.params.frames << " frames and " << boxes << " boxes to " << o.out_dir
            << "\n";
  return 0;
}

}  // namespace rdsf
