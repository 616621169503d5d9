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
    const double stride = params.stride_m * track.body.height_m / 1.75;
    double yaw = standing_yaw(rng, rng.uniform(-pi, pi));
    double phase = rng.uniform(0, 2 * pi);
    double gait = 0;
    double speed = rng.uniform(params.speed_min_mps, params.speed_max_mps);
    ArmPose arms = ArmPose::hanging;
    bool bending = false;
    double bend = 0;
    int stand_total = 0;
    bool walking = false;
    double target_x = x, target_z = z, target_yaw = yaw;
    int stand_frames = 0;
    for (int f = 0; f < frames; ++f) {
      if (!walking && stand_frames <= 0) {
        // choose what to do next: usually walk somewhere reachable in a straight line
        double tx = 0, tz = 0;
        bool found = false;
        if (rng.chance(0.75)) {
          // people mostly walk along the room, towards or away from the camera: of a few reachable spots,
          // usually take the one straightest along Z
          const bool along = rng.chance(params.along_room_share);
          double best_score = -1;
          for (int attempt = 0; attempt < 20; ++attempt) {
            double cx = 0, cz = 0;
            if (draw_spot(rng, room, params, camera, cx, cz) && std::hypot(cx - x, cz - z) > 1.0 &&
                clear_line(room, params, x, z, cx, cz)) {
              const double score = along ? std::abs(cz - z) / std::hypot(cx - x, cz - z) : 1.0;
              if (score > best_score) {
                best_score = score;
                tx = cx;
                tz = cz;
                found = true;
              }
              if (!along || attempt >= 8) break;
            }
          }
        }
        if (found) {
          walking = true;
          bending = false;
          target_x = tx;
          target_z = tz;
          speed = rng.uniform(params.speed_min_mps, params.speed_max_mps);
          if (params.poses) {
            const double pick = rng.uniform();
            arms = pick < 0.8 ? ArmPose::hanging : pick < 0.9 ? ArmPose::holding : pick < 0.95 ? ArmPose::phone : ArmPose::pockets;
          } else {
            arms = rng.chance(0.85) ? ArmPose::hanging : ArmPose::holding;
          }
        } else {
          stand_frames = rng.integer(20, 90);
          stand_total = stand_frames;
          target_yaw = standing_yaw(rng, yaw);
          standing_activity(rng, params, arms, bending, bend);
        }
      }
      const double dt = params.frame_interval_s;
      if (walking) {
        const double dx = target_x - x, dz = target_z - z;
        const double remaining = std::hypot(dx, dz);
        const double wanted = std::atan2(dx, dz);
        const double turn = std::clamp(wrap_angle(wanted - yaw), -3.0 * dt, 3.0 * dt);
        yaw = wrap_angle(yaw + turn);
        gait = std::min(1.0, gait + 3.0 * dt);
        // slow down while turning sharply, so paths stay smooth
        const double step = speed * dt * gait * std::max(0.2, std::cos(wrap_angle(wanted - yaw)));
        const double nx = x + step * std::sin(yaw), nz = z + step * std::cos(yaw);
        if (free_spot(room, params, nx, nz)) {
          x = nx;
          z = nz;
        } else {
          walking = false;
          stand_frames = rng.integer(5, 30);
          stand_total = stand_frames;
        }
        phase = std::fmod(phase + 2 * pi * step / stride, 2 * pi);
        if (remaining < 0.25) {
          walking = false;
          stand_frames = rng.integer(0, 60);
          stand_total = stand_frames;
          target_yaw = standing_yaw(rng, yaw);
        }
      } else {
        --stand_frames;
        gait = std::max(0.0, gait - 3.0 * dt);
        phase = std::fmod(phase + 2 * pi * speed * dt * gait / stride, 2 * pi);
        yaw = wrap_angle(yaw + std::clamp(wrap_angle(target_yaw - yaw), -2.0 * dt, 2.0 * dt));
      }
      PersonPose& pose = track.poses[static_cast<std::size_t>(f)];
      pose.position = {x, 0, z};
      pose.yaw_rad = yaw;
      pose.gait_phase = phase;
      pose.gait_amount = gait;
      const bool quiet = gait <= 0.5;
      pose.arms = !quiet && arms != ArmPose::holding && arms != ArmPose::pockets ? ArmPose::hanging : arms;
      if (!walking && bending && gait < 0.1) {
        // lean down and come back up over about 8 frames
        const int done = stand_total - stand_frames;
        const double ramp = std::clamp(std::min(done, stand_frames + 1) / 8.0, 0.0, 1.0);
        pose.posture = Posture::bending;
        pose.bend_rad = bend * ramp;
      }
      pose.present = true;
    }
    tracks.push_back(std::move(track));
  }
  return tracks;
}

}  // namespace rdsf::synth
