#pragma once
// Everything that decides a synthetic recording, with the defaults of rdsf-synth. The same parameters
// (and seed) always give the same frames, byte for byte.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "rdsf/core/parameter_table.hpp"
#include "rdsf/frame/camera_model.hpp"
#include "rdsf/synth/kinect_sensor.hpp"
#include "rdsf/synth/people_planner.hpp"
#include "rdsf/synth/room_generator.hpp"

namespace rdsf::synth {

struct SynthParams {
  int frames = 300;    ///< frames to render (at most 999999: names are 6 digits)
  int people_min = 0;  ///< people in the room of each clip: uniform in people_min..people_max
  int people_max = 3;
  std::uint64_t seed = 1;
  bool empty = false;  ///< the same rooms without people
  int width_px = 640;  ///< image size; both multiples of 8, 64x48 .. 1920x1440
  int height_px = 480;
  bool rgb = false;       ///< also render the registered colour image
  int clip_frames = 100;  ///< frames per clip; every clip is a new room, camera pose and people
  RoomParams room;
  PeopleParams people;
  KinectSensorParams sensor;
  /// Field of view of the depth image, degrees across the width and the height (--fov); both 0: the
  /// Kinect v1's intrinsics (fx = fy = 525 px at 640x480, 62.7 x 49.1 degrees) scaled to the image size.
  /// Only the camera changes: rooms, poses, people and sensor profiles are drawn the same (same seed).
  double fov_h_deg = 0;
  double fov_v_deg = 0;

  /// The depth image's pinhole model. With a field of view: fx = (width_px / 2) / tan(fov_h_deg / 2),
  /// fy = (height_px / 2) / tan(fov_v_deg / 2), principal point at the centre ((width_px - 1) / 2,
  /// (height_px - 1) / 2); else the Kinect v1's intrinsics scaled to the image size.
  CameraModel camera() const;
  /// Throws Error (one line naming the option: "--camera-roll 45: must lie in 0..20 degrees") for impossible
  /// values: each row of synth_parameters() checks its own, then what spans several of them.
  void validate() const;
};

/// rdsf-synth's parameters, each declared once (core/parameter_table.hpp): the rows of its options in --help
/// order, --frames to --clip-frames (without --seed: ParameterValue holds no unsigned 64-bit number, so
/// rdsf-synth declares it), then the variety's, --camera-height to --coherent-holes, then hidden rows for
/// the members --classic sets that have no option. A row's `classic` value is its value under --classic.
const ParameterTable<SynthParams>& synth_parameters();

/// `params` under --classic: every row's classic value (synth_parameters()), which turns off everything issue
/// 13 added (the generator of before: camera 0.7-1.2 m without roll, turn or motion, 16-bit Kinect captures
/// only, box rooms with their furniture, adults in plain clothes, basic poses, no pairs or sitting), for
/// comparisons.
SynthParams with_classic_values(SynthParams params);

/// Sets (option name, value) pairs on `params` through their rows, in order, then with `classic` the classic
/// values. A row with a classic value takes no given value under `classic` (--classic overrides it, unchecked
/// as before). Throws Error("--camera-roll 45: must lie in 0..20 degrees") for a refused value.
void set_synth_options(SynthParams& params, const std::vector<std::pair<std::string, ParameterValue>>& values,
                       bool classic);

/// rdsf-synth --frames FRAMES --people PEOPLE_MIN..PEOPLE_MAX --seed SEED, everything else its defaults: the
/// synthetic scene tests and benchmarks start from (people_scene(48, 1, 4, 17): 48 frames of 1-4 people, seed
/// 17), setting what else they need (rgb, clip_frames, ...) on the result.
SynthParams people_scene(int frames, int people_min, int people_max, std::uint64_t seed);

}  // namespace rdsf::synth
