#include "synth/synth_run.hpp"

#include <iostream>

#include "cli/progress.hpp"
#include "synth/synth_sequence.hpp"
#include "synth/synth_writer.hpp"

namespace rdsf {

int run_synth(SynthOptions o) {
  synth::parse_people_range(o.people, o.params.people_min, o.params.people_max);
  synth::parse_image_size(o.size, o.params.width_px, o.params.height_px);
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
