#pragma once
// The generator's own random numbers, identical on every compiler and standard library (the standard
// distributions are implementation-defined): xoshiro256** seeded through splitmix64, uniform numbers from
// the top 53 bits, normal numbers by Box-Muller. Every stream is derived from (seed, purpose, index), so a
// room, a person's path or a frame's sensor noise can be reproduced on its own.
#include <cstdint>

namespace rdsf::synth {

/// splitmix64 step: advances `state` and returns the next output.
std::uint64_t splitmix64(std::uint64_t& state);

/// A seed for one purpose ("room", "people", "sensor"...) and index (clip, frame) of a run with `seed`.
std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t purpose, std::uint64_t index);

/// Purposes for derive_seed.
enum Stream : std::uint64_t { stream_room = 1, stream_people = 2, stream_sensor = 3, stream_colour = 4, stream_profile = 5 };

class Rng {
 public:
  explicit Rng(std::uint64_t seed);
  std::uint64_t next();
  /// Uniform in [0, 1).
  double uniform();
  /// Uniform in [low, high).
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  /// Uniform integer in [low, high] (inclusive).
  int integer(int low, int high);
  /// True with probability p.
  bool chance(double p) { return uniform() < p; }
  /// Standard normal (Box-Muller, both values used).
  double normal();
  double normal(double mean, double sigma) { return mean + sigma * normal(); }

 private:
  std::uint64_t s_[4];
  double spare_ = 0;
  bool has_spare_ = false;
};

}  // namespace rdsf::synth
