#include "synth/person_model.hpp"

#include <algorithm>
#include <cmath>

namespace rdsf::synth {
namespace {

cv::Vec3b colour(Rng& rng, int low, int high) {
  return {static_cast<unsigned char>(rng.integer(low, high)),
          static_cast<unsigned char>(rng.integer(low, high)),
          static_cast<unsigned char>(rng.integer(low, high))};
}

/// Direction of a limb that hangs down, swung forward by `flexion` and sideways (outward) by `abduction`.
/// Local frame: x to the person's right... side = +1 right limb, -1 left limb; z forward.
Vec3 limb(double flexion, double abduction, double side) {
  const double ca = std::cos(abduction);
  return {side * std::sin(abduction), -ca * std::cos(flexion), ca * std::sin(flexion)};
}

}  // namespace

PersonBody random_body(Rng& rng) {
  PersonBody b;
  b.height_m = rng.uniform(1.5, 1.95);
  b.build = rng.uniform(0.85, 1.2);
  b.shirt = colour(rng, 20, 230);
  b.trousers = colour(rng, 20, 140);
  const int tone = rng.integer(60, 200);
  b.skin = {static_cast<unsigned char>(tone * 7 / 10), static_cast<unsigned char>(tone * 8 / 10),
            static_cast<unsigned char>(std::min(255, tone + 30))};
  b.hair = colour(rng, 10, 120);
  b.hair_dropout = static_cast<float>(rng.uniform(0.0, 0.35));
  return b;
}

void add_person_shapes(const PersonBody& body, const PersonPose& pose, int track,
                       std::vector<Shape>& shapes) {
  const double h = body.height_m, g = body.build;
  const double c = std::cos(pose.yaw_rad), n = std::sin(pose.yaw_rad);
  // local (x right of the person, y up, z forward) -> world
  auto world = [&](const Vec3& l) {
    return Vec3{pose.position.x + l.x * c + l.z * n, pose.position.y + l.y,
                pose.position.z - l.x * n + l.z * c};
  };
  auto capsule = [&](const Vec3& a, const Vec3& b, double r, cv::Vec3b col, float dropout = 0.0f) {
    shapes.push_back(make_capsule(world(a), world(b), r, col, track, dropout));
  };
  const double amount = pose.gait_amount;
  const double phase = pose.gait_phase;
  const double bob = 0.012 * amount * std::cos(2 * phase);
  const double sway = 0.015 * amount * std::sin(phase);

  // legs: hip flexion sinusoidal, knee flexed most in the swing phase
  const double hip_y = 0.52 * h + bob;
  const double thigh = 0.245 * h, shin = 0.25 * h;
  for (int side = -1; side <= 1; side += 2) {
    const double leg_phase = side < 0 ? phase : phase + 3.14159265358979;
    const double hip_flex = amount * 0.33 * std::sin(leg_phase);  // about 38 degrees peak to peak
    const double knee_flex =
        0.06 + amount * (0.15 + 0.85 * std::pow(std::max(0.0, std::cos(leg_phase)), 1.5));
    const Vec3 hip{side * 0.042 * h + sway, hip_y, 0};
    const Vec3 knee = hip + limb(hip_flex, 0.0, side) * thigh;
    const Vec3 ankle = knee + limb(hip_flex - knee_flex, 0.0, side) * shin;
    capsule(hip, knee, 0.048 * h * std::sqrt(g), body.trousers);  // thighs touch
    capsule(knee, ankle, 0.033 * h * std::sqrt(g), body.trousers);
    const Vec3 toe = ankle + Vec3{0, -0.01, 0.12 * h * 0.75};
    capsule(ankle, toe, 0.022 * h, cv::Vec3b(30, 30, 30), 0.1f);
  }
  // pelvis and torso
  capsule({-0.05 * h + sway, 0.55 * h + bob, 0}, {0.05 * h + sway, 0.55 * h + bob, 0}, 0.06 * h * g,
          body.trousers);
  const double chest_y = 0.77 * h + bob, waist_y = 0.58 * h + bob;
  for (int side = -1; side <= 1; side += 2) {
    capsule({side * 0.055 * h, chest_y, 0}, {side * 0.05 * h + sway, waist_y, 0}, 0.064 * h * g, body.shirt);
  }
  // neck and head
  const double neck_top = 0.875 * h + bob;
  capsule({0, 0.80 * h + bob, 0}, {0, neck_top, 0.005 * h}, 0.03 * h * g, body.skin);
  const double head_r = 0.058 * h;
  const Vec3 head_centre{0, h - head_r + bob, 0.01 * h};
  capsule(head_centre - Vec3{0, 0.012 * h, 0}, head_centre, head_r, body.skin);
  // hair: a cap over the back and top of the head
  capsule(head_centre + Vec3{0, 0.004 * h, -0.012 * h}, head_centre + Vec3{0, 0.004 * h, -0.012 * h},
          head_r * 0.97, body.hair, body.hair_dropout);

  // arms
  const double upper = 0.186 * h, fore = 0.19 * h;
  const double shoulder_y = 0.815 * h + bob;
  for (int side = -1; side <= 1; side += 2) {
    const Vec3 shoulder{side * 0.12 * h * std::sqrt(g), shoulder_y, 0};
    const double leg_phase = side < 0 ? phase : phase + 3.14159265358979;
    double flex = -amount * 0.3 * std::sin(leg_phase);  // arms swing against the leg on their side
    double abduction = 0.22 + 0.2 * (g - 1.0);
    double elbow = 0.3 + amount * 0.35 * std::max(0.0, std::sin(-leg_phase));
    if (pose.arms == ArmPose::holding) {
      flex = 0.25;
      elbow = 1.35;
      abduction = 0.14;
    } else if (pose.arms == ArmPose::phone && side > 0) {
      flex = 0.45;
      elbow = 2.5;
      abduction = 0.2;
    }
    Vec3 elbow_point = shoulder + limb(flex, abduction, side) * upper;
    Vec3 hand = elbow_point + limb(flex + elbow, abduction * 0.8, side) * fore;
    if (pose.arms == ArmPose::akimbo) {
      elbow_point = shoulder + limb(-0.15, 0.75, side) * upper;
      hand = {side * 0.09 * h * g, 0.575 * h + bob, 0.02 * h};
    }
    capsule(shoulder, elbow_point, 0.03 * h * g, body.shirt);
    capsule(elbow_point, hand, 0.022 * h * g, body.skin);
  }
}

}  // namespace rdsf::synth
