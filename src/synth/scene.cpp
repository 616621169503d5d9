#include "rdsf/synth/scene.hpp"

#include <cmath>

namespace rdsf::synth {

Shape make_capsule(const Vec3& a, const Vec3& b, double radius_m, cv::Vec3b colour, int owner,
                   float dropout) {
  Shape s;
  s.kind = ShapeKind::capsule;
  s.a = a;
  s.b = b;
  s.radius_m = radius_m;
  s.colour = colour;
  s.owner = owner;
  s.dropout = dropout;
  return s;
}

Shape make_box(const Vec3& centre, double yaw_rad, const Vec3& half_m, cv::Vec3b colour, float dropout) {
  Shape s;
  s.kind = ShapeKind::box;
  s.centre = centre;
  const double c = std::cos(yaw_rad), n = std::sin(yaw_rad);
  s.axis[0] = {c, 0, -n};
  s.axis[1] = {0, 1, 0};
  s.axis[2] = {n, 0, c};
  s.half_m = half_m;
  s.colour = colour;
  s.dropout = dropout;
  return s;
}

CameraAxes::CameraAxes(const CameraPose& pose) : origin{pose.x_m, pose.height_m, pose.z_m} {
  const double cy = std::cos(pose.yaw_rad), sy = std::sin(pose.yaw_rad);
  const double cp = std::cos(pose.pitch_rad), sp = std::sin(pose.pitch_rad);
  const double cr = std::cos(pose.roll_rad), sr = std::sin(pose.roll_rad);
  const Vec3 heading{sy, 0, cy}, right0{cy, 0, -sy}, up{0, 1, 0};
  forward = heading * cp - up * sp;
  const Vec3 down0 = up * (-cp) - heading * sp;
  right = right0 * cr + down0 * sr;
  down = down0 * cr - right0 * sr;
}

bool Footprint::contains(double px, double pz, double margin_m) const {
  const double dx = px - x, dz = pz - z;
  const double c = std::cos(yaw_rad), n = std::sin(yaw_rad);
  const double lx = dx * c - dz * n;  // inverse of the yaw used by make_box
  const double lz = dx * n + dz * c;
  return std::abs(lx) <= half_x + margin_m && std::abs(lz) <= half_z + margin_m;
}

bool Room::walkable(double x, double z, double margin_m) const {
  if (x < left_x + margin_m || x > right_x - margin_m || z > front_z - margin_m || z < back_z + margin_m) {
    return false;
  }
  for (const Footprint& f : footprints) {
    if (f.contains(x, z, margin_m)) return false;
  }
  return true;
}

}  // namespace rdsf::synth
