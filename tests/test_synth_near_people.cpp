// rdsf-synth's people near the camera and against walls (issue 34's cases): --people-distance and
// --wall-clearance reach the planner, and the defaults keep the earlier paths.
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

TEST(SynthNearPeople, ImpossibleValuesAreOneLineErrorsAndWriteNothing) {
  rdsf::test::TempDir dir("synth-near");
  for (const std::string bad : {"--people-distance 0.3..7", "--people-distance 3..2", "--people-distance near",
                                "--wall-clearance 0", "--wall-clearance 1.5"}) {
    const auto r = rdsf::test::run(rdsf::test::quote(rdsf::test::program("rdsf-synth")) + " --out " +
                                   rdsf::test::quote(dir / "out") + " --frames 1 " + bad);
    EXPECT_EQ(r.exit_code, 1) << bad << ": " << r.err;
    EXPECT_NE(r.err.find(bad.substr(0, bad.find(' '))), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << bad << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out")) << bad;
  }
}

}  // namespace
