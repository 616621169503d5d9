#pragma once
// Angles of the generator, in radians: pi, and wrapping into -pi..pi (headings, yaws of people and chairs).
namespace rdsf::synth {

constexpr double pi = 3.14159265358979323846;

/// `angle_rad` plus or minus whole turns (2 pi), in [-pi, pi].
inline double wrap_angle(double angle_rad) {
  while (angle_rad > pi) angle_rad -= 2 * pi;
  while (angle_rad < -pi) angle_rad += 2 * pi;
  return angle_rad;
}

}  // namespace rdsf::synth
