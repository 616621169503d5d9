#pragma once
// The synthetic scene the benchmarks and the performance report time: rdsf-synth's default rooms at
// 640x480 with 2-4 people, seed 11, so that their figures speak of the same frames.
#include "rdsf/synth/synth_params.hpp"

namespace rdsf::bench {

/// `frames` frames of the benchmark scene, with the registered colour image when `rgb`.
inline synth::SynthParams bench_scene(int frames, bool rgb) {
  synth::SynthParams p = synth::people_scene(frames, 2, 4, 11);
  p.rgb = rgb;
  return p;
}

}  // namespace rdsf::bench
