#include "synth/synth_run.hpp"

#include <iostream>

#include "rdsf/core/error.hpp"

#include "cli/progress.hpp"
#include "rdsf/synth/synth_sequence.hpp"
#include "rdsf/synth/synth_writer.hpp"

namespace rdsf {
namespace {

// --people as given ("2", not "2..2").
std::string people_text(const SynthOptions& o) {
  std::string text;
  for (const auto& [name, value] : o.values) {
    if (name == "people") text = parameter_text(value);
  }
  return text;
}

}  // namespace

int run_synth(SynthOptions o) {
  synth::set_synth_options(o.params, o.values, o.classic);
  o.params.validate();
  synth::SynthSequence sequence(o.params);  // validated before anything touches the folder
  synth::prepare_output_folder(o.out_dir, o.force);
  synth::SynthWriter writer(o.out_dir, o.params, o.force);
  std::cerr << "rdsf-synth: " << o.params.frames << " frames " << o.params.width_px << "x"
            << o.params.height_px << (o.params.empty ? ", no people" : ", people " + people_text(o)) << ", seed "
            << o.params.seed << " -> " << o.out_dir << "\n";
  cli::Progress progress(std::cerr, "frames", o.params.frames);
  long long boxes = 0;
  for (int i = 0; i < o.params.frames; ++i) {
    if (i % o.params.clip_frames == 0) writer.add_clip(sequence.describe_clip(i / o.params.clip_frames));
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
