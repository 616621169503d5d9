#include "synth/people_planner.hpp"

#include <algorithm>
#include <cmath>

namespace rdsf::synth {
namespace {

constexpr double pi = 3.14159265358979323846;

double wrap(double angle) {
  while (angle > pi) angle -= 2 * pi;
  while (angle < -pi) angle += 2 * pi;
  return angle;
}

/// Where a person who stops turns: mostly to face the room (the camera) or away from it, some keep
/// their heading (often sideways to the camera).
double standing_yaw(Rng& rng, double yaw) {
  const double facing = rng.uniform();
  if (facing < 0.5) return wrap(pi + rng.uniform(-0.8, 0.8));
  if (facing < 0.88) return rng.uniform(-0.8, 0.8);
  return yaw;
}

constexpr double clearance_m = 0.5;  // from walls and furniture

bool free_spot(const Room& room, const PeopleParams& p, double x, double z) {
  return z >= p.nearest_m && z <= p.farthest_m && room.walkable(x, z, clearance_m);
}

bool draw_spot(Rng& rng, const Room& room, const PeopleParams& p, double& x, double& z) {
  for (int attempt = 0; attempt < 60; ++attempt) {
    x = rng.uniform(room.left_x, room.right_x);
    z = rng.uniform(p.nearest_m, std::min(p.farthest_m, room.front_z));
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

std::vector<PersonTrack> plan_people(Rng& rng, const Room& room, int count, int frames, int first_track,
                                     const PeopleParams& params) {
  std::vector<PersonTrack> tracks;
  for (int slot = 0; slot < count; ++slot) {
    PersonTrack track;
    track.track = first_track + slot;
    track.body = random_body(rng);
    track.poses.resize(static_cast<std::size_t>(frames));
    double x = 0, z = 0;
    if (!draw_spot(rng, room, params, x, z)) {
      tracks.push_back(track);  // no room for this person: never present
      continue;
    }
    const double stride = params.stride_m * track.body.height_m / 1.75;
    double yaw = standing_yaw(rng, rng.uniform(-pi, pi));
    double phase = rng.uniform(0, 2 * pi);
    double gait = 0;
    double speed = rng.uniform(params.speed_min_mps, params.speed_max_mps);
    ArmPose arms = ArmPose::hanging;
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
            if (draw_spot(rng, room, params, cx, cz) && std::hypot(cx - x, cz - z) > 1.0 &&
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
          target_x = tx;
          target_z = tz;
          speed = rng.uniform(params.speed_min_mps, params.speed_max_mps);
          arms = rng.chance(0.85) ? ArmPose::hanging : ArmPose::holding;
        } else {
          stand_frames = rng.integer(20, 90);
          target_yaw = standing_yaw(rng, yaw);
          const double pick = rng.uniform();
          arms = pick < 0.6    ? ArmPose::hanging
                 : pick < 0.75 ? ArmPose::phone
                 : pick < 0.88 ? ArmPose::akimbo
                               : ArmPose::holding;
        }
      }
      const double dt = params.frame_interval_s;
      if (walking) {
        const double dx = target_x - x, dz = target_z - z;
        const double remaining = std::hypot(dx, dz);
        const double wanted = std::atan2(dx, dz);
        const double turn = std::clamp(wrap(wanted - yaw), -3.0 * dt, 3.0 * dt);
        yaw = wrap(yaw + turn);
        gait = std::min(1.0, gait + 3.0 * dt);
        // slow down while turning sharply, so paths stay smooth
        const double step = speed * dt * gait * std::max(0.2, std::cos(wrap(wanted - yaw)));
        const double nx = x + step * std::sin(yaw), nz = z + step * std::cos(yaw);
        if (free_spot(room, params, nx, nz)) {
          x = nx;
          z = nz;
        } else {
          walking = false;
          stand_frames = rng.integer(5, 30);
        }
        phase = std::fmod(phase + 2 * pi * step / stride, 2 * pi);
        if (remaining < 0.25) {
          walking = false;
          stand_frames = rng.integer(0, 60);
          target_yaw = standing_yaw(rng, yaw);
        }
      } else {
        --stand_frames;
        gait = std::max(0.0, gait - 3.0 * dt);
        phase = std::fmod(phase + 2 * pi * speed * dt * gait / stride, 2 * pi);
        yaw = wrap(yaw + std::clamp(wrap(target_yaw - yaw), -2.0 * dt, 2.0 * dt));
      }
      PersonPose& pose = track.poses[static_cast<std::size_t>(f)];
      pose.position = {x, 0, z};
      pose.yaw_rad = yaw;
      pose.gait_phase = phase;
      pose.gait_amount = gait;
      pose.arms = gait > 0.5 && (arms == ArmPose::phone || arms == ArmPose::akimbo) ? ArmPose::hanging : arms;
      pose.present = true;
    }
    tracks.push_back(std::move(track));
  }
  return tracks;
}

}  // namespace rdsf::synth
