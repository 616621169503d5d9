#pragma once
// rdsf-synth's work: check the options and the output folder, render every frame, write the set.
#include <string>
#include <utility>
#include <vector>

#include "rdsf/synth/synth_params.hpp"

namespace rdsf {

struct SynthOptions {
  std::string out_dir;
  /// The values of synth_parameters()' options (given, from --config or the defaults), set on params by run_synth.
  std::vector<std::pair<std::string, ParameterValue>> values;
  bool classic = false;  ///< the rows' classic values (--classic), after the other options
  bool force = false;
  std::string command_line;  ///< recorded in synth.yml
  synth::SynthParams params;
};

/// Returns the process exit code.
int run_synth(SynthOptions options);

}  // namespace rdsf
