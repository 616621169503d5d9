#include "rdsf/synth/person_model.hpp"

#include <algorithm>
#include <cmath>

#include "rdsf/synth/angle.hpp"

namespace rdsf::synth {
namespace {

cv::Vec3b colour(Rng& rng, int low, int high) {
  return {static_cast<unsigned char>(rng.integer(low, high)),
          static_cast<unsigned char>(rng.integer(low, high)),
          static_cast<unsigned char>(rng.integer(low, high))};
}

/// Direction of a limb that hangs down, swung forward by `flexion` and sideways (outward) by `abduction`.
/// Local frame: x to the person's right, y up, z forward; side = +1 right limb, -1 left limb.
Vec3 limb(double flexion, double abduction, double side) {
  const double ca = std::cos(abduction);
  return {side * std::sin(abduction), -ca * std::cos(flexion), ca * std::sin(flexion)};
}

/// The shapes of one person in one pose, appended in steps that share the person's frame: legs, trunk and
/// clothes, neck and head, things on the back, arms, things in the hands (in that order, always).
class PersonShapes {
 public:
  PersonShapes(const PersonBody& person, const PersonPose& posed, int owner, std::vector<Shape>& out)
      : body(person), pose(posed), track(owner), shapes(out), h(body.height_m), g(body.build),
        c(std::cos(pose.yaw_rad)), n(std::sin(pose.yaw_rad)), sitting(pose.posture == Posture::sitting),
        amount(sitting ? 0.0 : pose.gait_amount), phase(pose.gait_phase), bob(0.012 * amount * std::cos(2 * phase)),
        sway(0.015 * amount * std::sin(phase)), thigh(0.245 * h), shin(0.25 * h), thigh_r(0.048 * h * std::sqrt(g)),
        // the standing body is built with the hips at 0.52 h; sitting lowers them onto the seat and a little back
        hip_y(sitting ? pose.seat_height_m + thigh_r : 0.52 * h + bob), lift(hip_y - (0.52 * h + bob)),
        hip_z(sitting ? -0.3 * thigh : 0.0),
        bend(pose.posture == Posture::bending ? pose.bend_rad : (sitting ? -0.08 : 0.0)), cb(std::cos(bend)),
        sb(std::sin(bend)), upright(lift == 0 && hip_z == 0 && bend == 0), loose(body.looseness),
        chest_y(0.77 * h + bob), waist_y(0.58 * h + bob), torso_r(0.064 * h * g * loose) {}

  // legs: hip flexion sinusoidal, knee flexed most in the swing phase; sitting: thighs forward, shins down
  void add_legs() {
    const cv::Vec3b leg_colour = body.garment == Garment::trousers ? body.trousers : body.skin;
    for (int side = -1; side <= 1; side += 2) {
      const Vec3 hip{side * 0.042 * h + sway, hip_y, hip_z};
      Vec3 knee, ankle;
      if (sitting) {
        knee = hip + limb(1.45, 0.08, side) * thigh;
        ankle = knee + limb(0.2, 0.02, side) * shin;
        ankle.y = std::max(ankle.y, 0.03 * h);
      } else {
        const double leg_phase = side < 0 ? phase : phase + pi;
        const double hip_flex = amount * 0.33 * std::sin(leg_phase);  // about 38 degrees peak to peak
        const double knee_flex = 0.06 + amount * (0.15 + 0.85 * std::pow(std::max(0.0, std::cos(leg_phase)), 1.5));
        knee = hip + limb(hip_flex, 0.0, side) * thigh;
        ankle = knee + limb(hip_flex - knee_flex, 0.0, side) * shin;
      }
      capsule(hip, knee, thigh_r, leg_colour);  // thighs touch
      capsule(knee, ankle, 0.033 * h * std::sqrt(g), leg_colour);
      const Vec3 toe = ankle + Vec3{0, -0.01, 0.12 * h * 0.75};
      capsule(ankle, toe, 0.022 * h, cv::Vec3b(30, 30, 30), 0.1f);
    }
  }

  // pelvis and torso (loose clothes are wider; a belly adds depth at the waist), skirt, dress and coat
  void add_trunk() {
    upper_capsule({-0.05 * h + sway, 0.55 * h + bob, 0}, {0.05 * h + sway, 0.55 * h + bob, 0}, 0.06 * h * g,
                  body.garment == Garment::trousers ? body.trousers : body.shirt);
    for (int side = -1; side <= 1; side += 2) {
      upper_capsule({side * 0.055 * h, chest_y, 0}, {side * 0.05 * h + sway, waist_y, 0}, torso_r, body.shirt);
    }
    if (body.belly > 0.05) {
      upper_capsule({-0.03 * h, 0.63 * h + bob, 0.02 * h}, {0.03 * h, 0.63 * h + bob, 0.02 * h},
                    torso_r * (0.9 + 0.2 * body.belly), body.shirt);
    }
    // skirt, dress and coat: wide capsules from the waist down over the legs (they do not swing)
    if (body.garment != Garment::trousers) {
      const double top = body.garment == Garment::dress ? 0.62 * h : 0.56 * h;
      const double bottom = (body.garment == Garment::dress ? 0.3 : 0.36) * h;
      const double r = 0.082 * h * g * (sitting ? 1.0 : 1.05);
      if (sitting) {
        upper_capsule({0, top, 0}, {0, hip_y - lift + 0.02, 0.35 * thigh}, r, body.trousers);
      } else {
        upper_capsule({0, top + bob, 0}, {0, bottom + bob, 0.01 * h}, r, body.trousers);
      }
    }
    if (body.coat) {
      for (int side = -1; side <= 1; side += 2) {
        upper_capsule({side * 0.06 * h, chest_y, -0.005 * h}, {side * 0.06 * h, waist_y, -0.005 * h}, torso_r * 1.12,
                      body.bag);
        if (!sitting) {
          capsule({side * 0.065 * h + sway, waist_y, -0.01 * h}, {side * 0.07 * h + sway, 0.3 * h, -0.005 * h},
                  0.07 * h * g, body.bag);
        }
      }
    }
  }

  // neck and head (hair: a cap over the back and top; long hair down to the shoulders; a bun)
  void add_head() {
    const double neck_top = 0.875 * h + bob;
    upper_capsule({0, 0.80 * h + bob, 0}, {0, neck_top, 0.005 * h}, 0.03 * h * g, body.skin);
    const double head_r = (h < 1.45 ? 0.068 : 0.058) * h;  // children have larger heads for their height
    const Vec3 head_centre{0, h - head_r + bob, 0.01 * h};
    upper_capsule(head_centre - Vec3{0, 0.012 * h, 0}, head_centre, head_r, body.skin);
    const Vec3 cap = head_centre + Vec3{0, 0.004 * h, -0.012 * h};
    upper_capsule(cap, cap, head_r * 0.97, body.hair, body.hair_dropout);
    if (body.hair_style == HairStyle::long_hair) {
      upper_capsule(head_centre + Vec3{0, 0, -0.4 * head_r}, Vec3{0, 0.8 * h + bob, -0.035 * h}, head_r * 0.75,
                    body.hair, body.hair_dropout);
    } else if (body.hair_style == HairStyle::bun) {
      const Vec3 bun = head_centre + Vec3{0, 0.5 * head_r, -1.0 * head_r};
      upper_capsule(bun, bun, head_r * 0.45, body.hair, body.hair_dropout);
    }
  }

  // things on the back and at the side
  void add_carried_on_body() {
    if (body.carried == Carried::backpack) {
      upper_box({0, 0.71 * h + bob, -torso_r - body.bag_half_m.z}, body.bag_half_m, body.bag, -0.05);
    } else if (body.carried == Carried::shoulder_bag) {
      upper_box({-(0.1 * h * g + body.bag_half_m.x + 0.01), 0.5 * h + bob, 0.0}, body.bag_half_m, body.bag);
    }
  }

  // arms (the hands kept for add_held)
  void add_arms() {
    ArmPose arms = pose.arms;
    if (body.carried == Carried::box || body.carried == Carried::tray) arms = ArmPose::holding;
    const double upper_arm = 0.186 * h, fore = 0.19 * h;
    const double shoulder_y = 0.815 * h + bob;
    const double sleeve = loose > 1.0 ? 1.0 + 0.6 * (loose - 1.0) : 1.0;
    const bool coat_sleeves = body.coat;
    for (int side = -1; side <= 1; side += 2) {
      const Vec3 shoulder{side * 0.12 * h * std::sqrt(g), shoulder_y, 0};
      const double leg_phase = side < 0 ? phase : phase + pi;
      double flex = -amount * 0.3 * std::sin(leg_phase);  // arms swing against the leg on their side
      double abduction = 0.22 + 0.2 * (g - 1.0) + (body.belly > 0.05 ? 0.1 : 0.0);
      double elbow = 0.3 + amount * 0.35 * std::max(0.0, std::sin(-leg_phase));
      bool hand_set = false;
      Vec3 elbow_point, hand;
      switch (arms) {
        case ArmPose::holding: flex = 0.25; elbow = 1.35; abduction = 0.14; break;
        case ArmPose::phone:
          if (side > 0) { flex = 0.45; elbow = 2.5; abduction = 0.2; }
          break;
        case ArmPose::raised: flex = 0.15; abduction = 2.65; elbow = 0.15; break;
        case ArmPose::out: flex = 0.1; abduction = 1.45; elbow = 0.1; break;
        case ArmPose::pointing:
          if (side > 0) { flex = 1.45; abduction = 0.15; elbow = 0.05; }
          break;
        case ArmPose::waving:
          if (side > 0) { flex = 0.2; abduction = 2.3; elbow = 0.7; }
          break;
        case ArmPose::crossed:
          elbow_point = shoulder + limb(0.3, 0.12, side) * upper_arm;
          hand = {-side * 0.07 * h, 0.7 * h + bob, torso_r + 0.03 * h};
          hand_set = true;
          break;
        case ArmPose::pockets:
          elbow_point = shoulder + limb(-0.12, 0.32, side) * upper_arm;
          hand = {side * 0.085 * h * g, 0.5 * h + bob, 0.035 * h * g};
          hand_set = true;
          break;
        case ArmPose::akimbo:
          elbow_point = shoulder + limb(-0.15, 0.75, side) * upper_arm;
          hand = {side * 0.09 * h * g, 0.575 * h + bob, 0.02 * h};
          hand_set = true;
          break;
        case ArmPose::hanging: break;
      }
      // hanging arms of a bending person hang straight down in the world, not along the torso
      if (arms == ArmPose::hanging && pose.posture == Posture::bending) flex += bend;
      if (!hand_set) {
        elbow_point = shoulder + limb(flex, abduction, side) * upper_arm;
        hand = elbow_point + limb(flex + elbow, abduction * 0.8, side) * fore;
      }
      hands[side > 0 ? 1 : 0] = hand;
      upper_capsule(shoulder, elbow_point, 0.03 * h * g * sleeve * (coat_sleeves ? 1.25 : 1.0),
                    coat_sleeves ? body.bag : body.shirt);
      upper_capsule(elbow_point, hand, 0.022 * h * g * sleeve, body.skin);
    }
  }

  // things held in the hands
  void add_held() {
    if (body.carried == Carried::box || body.carried == Carried::tray) {
      const Vec3 mid = (hands[0] + hands[1]) * 0.5;
      const Vec3 centre{0, mid.y + (body.carried == Carried::box ? 0.3 * body.bag_half_m.y : 0.02),
                        mid.z + (body.carried == Carried::box ? 0.3 * body.bag_half_m.z : 0.0)};
      upper_box(centre, body.bag_half_m, body.bag);
    } else if (body.carried == Carried::handbag) {
      const Vec3& hand = hands[0];
      upper_box({hand.x - 0.01, hand.y - body.bag_half_m.y - 0.02, hand.z}, body.bag_half_m, body.bag);
    }
  }

 private:
  // local (x right of the person, y up, z forward) -> world
  Vec3 world(const Vec3& l) const {
    return Vec3{pose.position.x + l.x * c + l.z * n, pose.position.y + l.y, pose.position.z - l.x * n + l.z * c};
  }
  // the upper body, built standing, raised or lowered to the hips and leant forward by `bend` about them
  Vec3 upper(const Vec3& l) const {
    if (upright) return l;  // exactly the standing body
    const double dy = l.y + lift - hip_y, dz = l.z;
    return Vec3{l.x, hip_y + dy * cb - dz * sb, hip_z + dy * sb + dz * cb};
  }
  void capsule(const Vec3& a, const Vec3& b, double r, cv::Vec3b col, float dropout = 0.0f) {
    shapes.push_back(make_capsule(world(a), world(b), r, col, track, dropout));
  }
  void upper_capsule(const Vec3& a, const Vec3& b, double r, cv::Vec3b col, float dropout = 0.0f) {
    capsule(upper(a), upper(b), r, col, dropout);
  }
  void upper_box(const Vec3& centre, const Vec3& half, cv::Vec3b col, double tilt = 0.0) {
    // a box in the upper body's frame: its axes follow the lean (and an extra tilt about x)
    Shape s = make_box(world(upper(centre)), 0.0, half, col, 0.1f);
    const double ct = std::cos(bend + tilt), st = std::sin(bend + tilt);
    const Vec3 ax{c, 0, -n}, ay{n * st, ct, c * st}, az{n * ct, -st, c * ct};
    s.axis[0] = ax;
    s.axis[1] = ay;
    s.axis[2] = az;
    s.owner = track;
    shapes.push_back(s);
  }

  const PersonBody& body;
  const PersonPose& pose;
  const int track;
  std::vector<Shape>& shapes;
  const double h, g;  // height (m), build
  const double c, n;  // cos and sin of the yaw
  const bool sitting;
  const double amount, phase, bob, sway;  // gait: amount, phase, vertical bob and sideways sway (m)
  const double thigh, shin, thigh_r;
  const double hip_y, lift, hip_z, bend, cb, sb;
  const bool upright;
  const double loose, chest_y, waist_y, torso_r;
  Vec3 hands[2];  // set by add_arms(), for add_held()
};

}  // namespace

PersonBody random_body(Rng& rng, const BodyParams& params) {
  PersonBody b;
  if (params.varied_bodies) {
    const bool child = rng.chance(params.child_share);
    b.height_m = child ? rng.uniform(1.0, 1.45) : rng.uniform(1.5, 2.0);
    // builds skewed towards average: the mean of two draws, stretched
    b.build = child ? rng.uniform(0.85, 1.1) : 0.8 + 0.65 * 0.5 * (rng.uniform() + rng.uniform());
    b.belly = b.build > 1.15 ? rng.uniform(0.0, 1.0) * (b.build - 1.15) / 0.3 : 0.0;
  } else {
    b.height_m = rng.uniform(1.5, 1.95);
    b.build = rng.uniform(0.85, 1.2);
  }
  b.shirt = colour(rng, 20, 230);
  b.trousers = colour(rng, 20, 140);
  const int tone = rng.integer(60, 200);
  b.skin = {static_cast<unsigned char>(tone * 7 / 10), static_cast<unsigned char>(tone * 8 / 10),
            static_cast<unsigned char>(std::min(255, tone + 30))};
  b.hair = colour(rng, 10, 120);
  b.hair_dropout = static_cast<float>(rng.uniform(0.0, 0.35));
  if (!params.outfits) return b;
  const double hair = rng.uniform();
  b.hair_style = hair < 0.55 ? HairStyle::short_hair : hair < 0.85 ? HairStyle::long_hair : HairStyle::bun;
  const double garment = rng.uniform();
  b.garment = garment < 0.78 ? Garment::trousers : garment < 0.92 ? Garment::skirt : Garment::dress;
  b.coat = rng.chance(0.2);
  b.looseness = rng.chance(0.4) ? rng.uniform(1.05, 1.3) : 1.0;
  const double carried = rng.uniform();
  b.carried = carried < 0.55   ? Carried::nothing
              : carried < 0.7  ? Carried::backpack
              : carried < 0.8  ? Carried::shoulder_bag
              : carried < 0.88 ? Carried::handbag
              : carried < 0.95 ? Carried::box
                               : Carried::tray;
  b.bag = colour(rng, 15, 160);
  switch (b.carried) {
    case Carried::backpack: b.bag_half_m = {rng.uniform(0.12, 0.17), rng.uniform(0.16, 0.24), rng.uniform(0.06, 0.12)}; break;
    case Carried::shoulder_bag: b.bag_half_m = {rng.uniform(0.04, 0.07), rng.uniform(0.1, 0.16), rng.uniform(0.12, 0.2)}; break;
    case Carried::handbag: b.bag_half_m = {rng.uniform(0.04, 0.07), rng.uniform(0.08, 0.14), rng.uniform(0.1, 0.18)}; break;
    case Carried::box: b.bag_half_m = {rng.uniform(0.15, 0.28), rng.uniform(0.1, 0.22), rng.uniform(0.12, 0.22)}; break;
    case Carried::tray: b.bag_half_m = {rng.uniform(0.18, 0.25), 0.012, rng.uniform(0.12, 0.18)}; break;
    case Carried::nothing: break;
  }
  return b;
}

double torso_height_m(const PersonBody& body, const PersonPose& pose) {
  if (pose.posture == Posture::sitting) return pose.seat_height_m + 0.16 * body.height_m;
  return 0.65 * body.height_m - (pose.posture == Posture::bending ? 0.1 * body.height_m * std::sin(pose.bend_rad) : 0.0);
}

void add_person_shapes(const PersonBody& body, const PersonPose& pose, int track,
                       std::vector<Shape>& shapes) {
  PersonShapes person(body, pose, track, shapes);
  person.add_legs();
  person.add_trunk();
  person.add_head();
  person.add_carried_on_body();
  person.add_arms();
  person.add_held();
}

}  // namespace rdsf::synth
