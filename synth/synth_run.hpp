#pragma once
// rdsf-synth's work: check the options and the output folder, render every frame, write the set.
#include <string>

#include "synth/synth_params.hpp"

namespace rdsf {

struct SynthOptions {
  std::string out_dir;
  std::string people = "0..3";  ///< MIN..MAX
  std::string size = "640x480";
  bool force = false;
  std::string command_line;  ///< recorded in synth.yml
  synth::SynthParams params;
};

/// Returns the process exit code.
int run_synth(SynthOptions options);

}  // namespace rdsf
