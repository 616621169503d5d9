// rdsf-synth's people near the camera and against walls (issue 34's cases): --people-distance and
// --wall-clearance reach the planner, and the defaults keep the earlier paths; --near-clutter puts things close
// to the camera.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "rdsf/synth/people_planner.hpp"
#include "rdsf/synth/room_generator.hpp"
#include "support/test_support.hpp"

namespace {

using namespace rdsf::synth;

struct Placement {
  double nearest_z = 1e9;
  int near_a_wall = 0;  ///< standing or walking poses with a wall or furniture within 0.45 m
  int poses = 0;
};

Placement place(const PeopleParams& params) {
  Placement result;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    Rng room_rng(seed), people_rng(seed + 100);
    CameraPose camera;
    const Room room = generate_room(room_rng, {}, camera);
    for (const PersonTrack& t : plan_people(people_rng, room, 4, 200, 1, params, camera)) {
      for (const PersonPose& pose : t.poses) {
        if (!pose.present || pose.posture == Posture::sitting) continue;
        ++result.poses;
        result.nearest_z = std::min(result.nearest_z, pose.position.z);
        result.near_a_wall += room.walkable(pose.position.x, pose.position.z, 0.45) ? 0 : 1;
      }
    }
  }
  return result;
}

TEST(SynthNearPeople, DistanceAndClearanceReachThePlanner) {
  PeopleParams defaults;
  const Placement before = place(defaults);
  PeopleParams near = defaults;
  near.nearest_m = 0.8;
  near.clearance_m = 0.25;
  const Placement after = place(near);
  ASSERT_GT(before.poses, 1000);
  ASSERT_GT(after.poses, 1000);
  // The defaults: nobody nearer than 1.6 m (groups walk beside someone at most 0.75 m aside, not nearer),
  // nobody within 0.45 m of a wall or furniture.
  EXPECT_GE(before.nearest_z, 1.6 - 1e-9);
  EXPECT_EQ(before.near_a_wall, 0);
  // Nearer and against walls with the lever's values.
  EXPECT_LT(after.nearest_z, 1.2);
  EXPECT_GE(after.nearest_z, 0.8 - 1e-9);
  EXPECT_GT(after.near_a_wall, 50);
}

// --near-clutter: 1..N pieces of furniture within 0.6-1.6 m of the camera in every room (their footprints'
// centres, within 20 degrees of its heading); the default (0) keeps the room the same piece for piece.
TEST(SynthNearPeople, NearClutterStandsInFrontOfTheCameraAndTheDefaultKeepsTheRoom) {
  int rooms_with_near = 0, near_pieces = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    RoomParams plain, near;
    near.near_clutter_max = 3;
    Rng rng_plain(seed), rng_again(seed), rng_near(seed);
    CameraPose camera_plain, camera_again, camera_near;
    const Room room = generate_room(rng_plain, plain, camera_plain);
    const Room again = generate_room(rng_again, plain, camera_again);
    const Room with = generate_room(rng_near, near, camera_near);
    ASSERT_EQ(room.furniture.size(), again.furniture.size());
    // The pieces before the near ones are drawn as without the option.
    ASSERT_GE(with.footprints.size(), room.footprints.size());
    for (std::size_t i = 0; i < room.footprints.size(); ++i) {
      EXPECT_DOUBLE_EQ(with.footprints[i].x, room.footprints[i].x) << seed;
      EXPECT_DOUBLE_EQ(with.footprints[i].z, room.footprints[i].z) << seed;
    }
    int near_here = 0;
    for (std::size_t i = room.footprints.size(); i < with.footprints.size(); ++i) {
      const double dx = with.footprints[i].x - camera_near.x_m, dz = with.footprints[i].z - camera_near.z_m;
      const double distance = std::hypot(dx, dz);
      EXPECT_GE(distance, 0.6 - 1e-9) << seed;
      EXPECT_LE(distance, 1.6 + 1e-9) << seed;
      EXPECT_LE(std::abs(std::atan2(dx, dz) - camera_near.yaw_rad), 20.0 * M_PI / 180.0 + 1e-9) << seed;
      ++near_here;
    }
    EXPECT_LE(near_here, 3) << seed;
    near_pieces += near_here;
    rooms_with_near += near_here > 0 ? 1 : 0;
  }
  EXPECT_GE(rooms_with_near, 10);  // a piece finds no free spot to start from only in a crowded room
  EXPECT_GE(near_pieces, 15);
}

TEST(SynthNearPeople, ImpossibleValuesAreOneLineErrorsAndWriteNothing) {
  rdsf::test::TempDir dir("synth-near");
  for (const std::string bad : {"--people-distance 0.3..7", "--people-distance 3..2", "--people-distance near",
                                "--wall-clearance 0", "--wall-clearance 1.5", "--near-clutter 7", "--near-clutter -1"}) {
    const auto r = rdsf::test::run(rdsf::test::quote(rdsf::test::program("rdsf-synth")) + " --out " +
                                   rdsf::test::quote(dir / "out") + " --frames 1 " + bad);
    EXPECT_EQ(r.exit_code, 1) << bad << ": " << r.err;
    EXPECT_NE(r.err.find(bad.substr(0, bad.find(' '))), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << bad << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out")) << bad;
  }
}

}  // namespace
