#include "rdsf/synth/people_planner.hpp"

#include <algorithm>
#include <cmath>

#include "rdsf/synth/angle.hpp"

namespace rdsf::synth {
namespace {

/// Where a person who stops turns: mostly to face the room (the camera) or away from it, some keep
/// their heading (often sideways to the camera).
double standing_yaw(Rng& rng, double yaw) {
  const double facing = rng.uniform();
  if (facing < 0.5) return wrap_angle(pi + rng.uniform(-0.8, 0.8));
  if (facing < 0.88) return rng.uniform(-0.8, 0.8);
  return yaw;
}

bool free_spot(const Room& room, const PeopleParams& p, double x, double z) {
  return z >= p.nearest_m && z <= p.farthest_m && room.walkable(x, z, p.clearance_m);
}

/// A free spot of the room; most (in_view_share) in the camera's view: within 0.45 rad of its heading, at
/// nearest_m..farthest_m from it.
bool draw_spot(Rng& rng, const Room& room, const PeopleParams& p, const CameraPose& camera, double& x, double& z) {
  const bool in_view = p.in_view_share > 0 && rng.chance(p.in_view_share);
  for (int attempt = 0; attempt < 60; ++attempt) {
    if (in_view && attempt < 40) {
      const double r = rng.uniform(p.nearest_m, p.farthest_m), a = camera.yaw_rad + rng.uniform(-0.45, 0.45);
      x = camera.x_m + r * std::sin(a);
      z = camera.z_m + r * std::cos(a);
    } else {
      x = rng.uniform(room.left_x, room.right_x);
      z = rng.uniform(p.nearest_m, std::min(p.farthest_m, room.front_z));
    }
    if (free_spot(room, p, x, z)) return true;
  }
  return false;
}

bool clear_line(const Room& room, const PeopleParams& p, double x0, double z0, double x1, double z1) {
  const double distance = std::hypot(x1 - x0, z1 - z0);
  const int steps = std::max(2, static_cast<int>(distance / 0.1));
  for (int k = 0; k <= steps; ++k) {
    const double t = static_cast<double>(k) / steps;
    if (!free_spot(room, p, x0 + t * (x1 - x0), z0 + t * (z1 - z0))) return false;
  }
  return true;
}

}  // namespace

namespace {

/// What a person does while standing still, drawn once per stop: the arm pose, and whether they bend.
void standing_activity(Rng& rng, const PeopleParams& params, ArmPose& arms, bool& bending, double& bend_rad) {
  bending = false;
  bend_rad = 0;
  const double pick = rng.uniform();
  if (!params.poses) {
    arms = pick < 0.6 ? ArmPose::hanging : pick < 0.75 ? ArmPose::phone : pick < 0.88 ? ArmPose::akimbo : ArmPose::holding;
    return;
  }
  arms = pick < 0.34   ? ArmPose::hanging
         : pick < 0.44 ? ArmPose::phone
         : pick < 0.5  ? ArmPose::akimbo
         : pick < 0.56 ? ArmPose::holding
         : pick < 0.63 ? ArmPose::pockets
         : pick < 0.7  ? ArmPose::crossed
         : pick < 0.77 ? ArmPose::raised
         : pick < 0.83 ? ArmPose::out
         : pick < 0.88 ? ArmPose::pointing
         : pick < 0.92 ? ArmPose::waving
                       : ArmPose::hanging;
  if (pick >= 0.92) {  // bending down (to a table, to pick something up)
    bending = true;
    bend_rad = rng.uniform(0.4, 1.2);
  }
}

/// A person sitting on `seat` for the whole clip.
void plan_sitter(Rng& rng, const Seat& seat, PersonTrack& track) {
  const double pick = rng.uniform();
  const ArmPose arms = pick < 0.45 ? ArmPose::hanging : pick < 0.6 ? ArmPose::crossed : pick < 0.8 ? ArmPose::holding : ArmPose::phone;
  for (PersonPose& pose : track.poses) {
    pose.position = {seat.x, 0, seat.z};
    pose.yaw_rad = seat.yaw_rad;
    pose.posture = Posture::sitting;
    pose.seat_height_m = seat.height_m;
    pose.arms = arms;
    pose.present = true;
  }
}

/// A person walking and standing with `leader` (side by side, or a step behind): every frame they move
/// towards their place beside the leader, at most as fast as anyone walks, and turn at most 3 rad/s.
/// Returns false when there is no free place beside the leader at the start.
bool plan_companion(Rng& rng, const Room& room, const PeopleParams& params, const PersonTrack& leader,
                    PersonTrack& track) {
  const double side = (rng.chance(0.5) ? 1.0 : -1.0) * rng.uniform(0.5, 0.75);
  const double behind = rng.uniform(-0.35, 0.15);
  const bool face_leader = rng.chance(0.4);  // standing, they turn to talk
  const double dt = params.frame_interval_s;
  const double max_step = params.speed_max_mps * dt * 0.98;
  const double stride = params.stride_m * track.body.height_m / 1.75;
  auto place_of = [&](const PersonPose& l, double& px, double& pz) {
    const double c = std::cos(l.yaw_rad), n = std::sin(l.yaw_rad);
    px = l.position.x + side * c + behind * n;
    pz = l.position.z - side * n + behind * c;
  };
  const PersonPose& first = leader.poses.front();
  if (!first.present) return false;
  double x = 0, z = 0;
  place_of(first, x, z);
  if (!free_spot(room, params, x, z)) return false;
  double yaw = first.yaw_rad, phase = rng.uniform(0, 2 * pi), gait = 0;
  ArmPose arms = ArmPose::hanging;
  bool bending = false;
  double bend = 0;
  standing_activity(rng, params, arms, bending, bend);
  for (std::size_t f = 0; f < track.poses.size(); ++f) {
    const PersonPose& l = leader.poses[f];
    double tx = x, tz = z;
    if (l.present) place_of(l, tx, tz);
    const double dx = tx - x, dz = tz - z;
    const double distance = std::hypot(dx, dz);
    double step = std::min(distance, max_step);
    if (step < 0.004) step = 0;
    const double nx = step > 0 ? x + dx / distance * step : x, nz = step > 0 ? z + dz / distance * step : z;
    if (step > 0 && free_spot(room, params, nx, nz)) {
      x = nx;
      z = nz;
    } else {
      step = 0;
    }
    const bool moving = step > 0.2 * max_step;
    double wanted = l.yaw_rad;
    if (moving) {
      wanted = std::atan2(dx, dz);
    } else if (face_leader && l.gait_amount < 0.1) {
      wanted = std::atan2(l.position.x - x, l.position.z - z);
    }
    yaw = wrap_angle(yaw + std::clamp(wrap_angle(wanted - yaw), -2.9 * dt, 2.9 * dt));
    gait = moving ? std::min(1.0, gait + 3.0 * dt) : std::max(0.0, gait - 3.0 * dt);
    phase = std::fmod(phase + 2 * pi * step / stride, 2 * pi);
    PersonPose& pose = track.poses[f];
    pose.position = {x, 0, z};
    pose.yaw_rad = yaw;
    pose.gait_phase = phase;
    pose.gait_amount = gait;
    pose.arms = gait > 0.5 && arms != ArmPose::holding ? ArmPose::hanging : arms;
    pose.posture = !moving && bending && gait < 0.1 ? Posture::bending : Posture::standing;
    pose.bend_rad = pose.posture == Posture::bending ? bend : 0.0;
    pose.present = true;
  }
  return true;
}

// A person who walks in straight lines between reachable spots (mostly along the room) and stands in
// between (turning, bending, the arms' activity): plan_people's default kind. One pose per frame, in order.
class Walker {
 public:
  Walker(Rng& rng, const Room& room, const PeopleParams& params, const CameraPose& camera, const PersonBody& body,
         double x, double z)
      : rng_(rng), room_(room), params_(params), camera_(camera), stride_(params.stride_m * body.height_m / 1.75),
        x_(x), z_(z), target_x_(x), target_z_(z) {
    // the draws in this order: the yaw, the gait's phase, the speed
    yaw_ = standing_yaw(rng_, rng_.uniform(-pi, pi));
    target_yaw_ = yaw_;
    phase_ = rng_.uniform(0, 2 * pi);
    speed_ = rng_.uniform(params_.speed_min_mps, params_.speed_max_mps);
  }

  void next_pose(PersonPose& pose) {
    if (!walking_ && stand_frames_ <= 0) choose_next();
    const double dt = params_.frame_interval_s;
    if (walking_) {
      walk(dt);
    } else {
      --stand_frames_;
      gait_ = std::max(0.0, gait_ - 3.0 * dt);
      phase_ = std::fmod(phase_ + 2 * pi * speed_ * dt * gait_ / stride_, 2 * pi);
      yaw_ = wrap_angle(yaw_ + std::clamp(wrap_angle(target_yaw_ - yaw_), -2.0 * dt, 2.0 * dt));
    }
    pose.position = {x_, 0, z_};
    pose.yaw_rad = yaw_;
    pose.gait_phase = phase_;
    pose.gait_amount = gait_;
    const bool quiet = gait_ <= 0.5;
    pose.arms = !quiet && arms_ != ArmPose::holding && arms_ != ArmPose::pockets ? ArmPose::hanging : arms_;
    if (!walking_ && bending_ && gait_ < 0.1) {
      // lean down and come back up over about 8 frames
      const int done = stand_total_ - stand_frames_;
      const double ramp = std::clamp(std::min(done, stand_frames_ + 1) / 8.0, 0.0, 1.0);
      pose.posture = Posture::bending;
      pose.bend_rad = bend_ * ramp;
    }
    pose.present = true;
  }

 private:
  // What to do next: usually walk somewhere reachable in a straight line, else stand a while.
  void choose_next() {
    double tx = 0, tz = 0;
    if (rng_.chance(0.75) && reachable_target(tx, tz)) {
      walking_ = true;
      bending_ = false;
      target_x_ = tx;
      target_z_ = tz;
      speed_ = rng_.uniform(params_.speed_min_mps, params_.speed_max_mps);
      if (params_.poses) {
        const double pick = rng_.uniform();
        arms_ = pick < 0.8 ? ArmPose::hanging : pick < 0.9 ? ArmPose::holding : pick < 0.95 ? ArmPose::phone : ArmPose::pockets;
      } else {
        arms_ = rng_.chance(0.85) ? ArmPose::hanging : ArmPose::holding;
      }
    } else {
      stand_frames_ = rng_.integer(20, 90);
      stand_total_ = stand_frames_;
      target_yaw_ = standing_yaw(rng_, yaw_);
      standing_activity(rng_, params_, arms_, bending_, bend_);
    }
  }

  // People mostly walk along the room, towards or away from the camera: of a few reachable spots, usually
  // the one straightest along Z. False when none of 20 draws is reachable.
  bool reachable_target(double& tx, double& tz) {
    const bool along = rng_.chance(params_.along_room_share);
    double best_score = -1;
    bool found = false;
    for (int attempt = 0; attempt < 20; ++attempt) {
      double cx = 0, cz = 0;
      if (draw_spot(rng_, room_, params_, camera_, cx, cz) && std::hypot(cx - x_, cz - z_) > 1.0 &&
          clear_line(room_, params_, x_, z_, cx, cz)) {
        const double score = along ? std::abs(cz - z_) / std::hypot(cx - x_, cz - z_) : 1.0;
        if (score > best_score) {
          best_score = score;
          tx = cx;
          tz = cz;
          found = true;
        }
        if (!along || attempt >= 8) break;
      }
    }
    return found;
  }

  // One frame's step towards the target: turning at most 3 rad/s, slowing down while turning sharply (so
  // paths stay smooth); blocked, or arrived within 25 cm, the person stands.
  void walk(double dt) {
    const double dx = target_x_ - x_, dz = target_z_ - z_;
    const double remaining = std::hypot(dx, dz);
    const double wanted = std::atan2(dx, dz);
    const double turn = std::clamp(wrap_angle(wanted - yaw_), -3.0 * dt, 3.0 * dt);
    yaw_ = wrap_angle(yaw_ + turn);
    gait_ = std::min(1.0, gait_ + 3.0 * dt);
    const double step = speed_ * dt * gait_ * std::max(0.2, std::cos(wrap_angle(wanted - yaw_)));
    const double nx = x_ + step * std::sin(yaw_), nz = z_ + step * std::cos(yaw_);
    if (free_spot(room_, params_, nx, nz)) {
      x_ = nx;
      z_ = nz;
    } else {
      walking_ = false;
      stand_frames_ = rng_.integer(5, 30);
      stand_total_ = stand_frames_;
    }
    phase_ = std::fmod(phase_ + 2 * pi * step / stride_, 2 * pi);
    if (remaining < 0.25) {
      walking_ = false;
      stand_frames_ = rng_.integer(0, 60);
      stand_total_ = stand_frames_;
      target_yaw_ = standing_yaw(rng_, yaw_);
    }
  }

  Rng& rng_;
  const Room& room_;
  const PeopleParams& params_;
  const CameraPose& camera_;
  const double stride_;  // m, scaled with the body's height
  double x_, z_;
  double target_x_, target_z_;
  double yaw_ = 0, target_yaw_ = 0, phase_ = 0, gait_ = 0, speed_ = 0;
  ArmPose arms_ = ArmPose::hanging;
  bool bending_ = false;
  double bend_ = 0;
  int stand_total_ = 0, stand_frames_ = 0;
  bool walking_ = false;
};

}  // namespace

std::vector<PersonTrack> plan_people(Rng& rng, const Room& room, int count, int frames, int first_track,
                                     const PeopleParams& params, const CameraPose& camera) {
  std::vector<PersonTrack> tracks;
  std::vector<Seat> seats = room.seats;
  std::vector<bool> sitting;
  for (int slot = 0; slot < count; ++slot) {
    PersonTrack track;
    track.track = first_track + slot;
    track.body = random_body(rng, params.body);
    track.poses.resize(static_cast<std::size_t>(frames));
    // sitting on a free chair for the whole clip
    if (params.poses && !seats.empty() && rng.chance(params.sitting_share)) {
      const std::size_t k = static_cast<std::size_t>(rng.integer(0, static_cast<int>(seats.size()) - 1));
      plan_sitter(rng, seats[k], track);
      seats.erase(seats.begin() + static_cast<std::ptrdiff_t>(k));
      sitting.push_back(true);
      tracks.push_back(std::move(track));
      continue;
    }
    // walking and standing with the person planned before (a pair, a group)
    if (params.group_share > 0 && slot > 0 && !sitting.back() && rng.chance(params.group_share) &&
        plan_companion(rng, room, params, tracks.back(), track)) {
      sitting.push_back(false);
      tracks.push_back(std::move(track));
      continue;
    }
    sitting.push_back(false);
    double x = 0, z = 0;
    if (!draw_spot(rng, room, params, camera, x, z)) {
      tracks.push_back(track);  // no room for this person: never present
      continue;
    }
    Walker walker(rng, room, params, camera, track.body, x, z);
    for (PersonPose& pose : track.poses) walker.next_pose(pose);
    tracks.push_back(std::move(track));
  }
  return tracks;
}

}  // namespace rdsf::synth
