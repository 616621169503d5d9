#pragma once
// rdsf-synth's work: check the options and the output folder, render every frame, write the set.
#include <string>

#include "rdsf/synth/synth_params.hpp"

namespace rdsf {

struct SynthOptions {
  std::string out_dir;
  std::string people = "0..3";  ///< MIN..MAX
  std::string size = "640x480";
  std::string fov = "kinect";  ///< --fov: HxV degrees, or kinect (the Kinect v1's model scaled to --size)
  // variety (issue 13), as given on the command line; parsed into params by run_synth
  std::string camera_height = "0.5..1.6";
  std::string camera_pitch = "-3..6";
  std::string people_distance = "1.6..7";
  std::string clutter = "3..9";
  std::string eight_bit_step = "12..28";
  std::string outfits = "on", poses = "on", bodies = "on", room_kinds = "on";
  bool classic = false;  ///< turn every variety off (SynthParams::set_classic), after the other options
  bool force = false;
  std::string command_line;  ///< recorded in synth.yml
  synth::SynthParams params;
};

/// Returns the process exit code.
int run_synth(SynthOptions options);

}  // namespace rdsf
