#pragma once
// An articulated person made of capsules: head, neck, torso (two capsules side by side, so it is wider
// than deep), pelvis, upper and lower arms, upper and lower legs and feet, with proportions of an adult
// body scaled to its height. Forward kinematics turn a pose (position, heading, gait phase, arm pose) into
// capsules in world coordinates.
#include <opencv2/core.hpp>
#include <vector>

#include "synth/random.hpp"
#include "synth/scene.hpp"

namespace rdsf::synth {

struct PersonBody {
  double height_m = 1.75;  ///< 1.5-1.95 m
  double build = 1.0;      ///< girth factor on every radius, 0.85-1.2
  cv::Vec3b shirt{90, 60, 40}, trousers{60, 50, 40}, skin{120, 150, 200}, hair{20, 30, 40};  ///< BGR
  float hair_dropout = 0.2f;  ///< dark hair loses readings
};

enum class ArmPose {
  hanging,  ///< arms by the body (they swing when walking)
  phone,    ///< one hand at the face
  holding,  ///< both forearms forward, as when carrying something
  akimbo,   ///< hands on the hips, elbows out
};

struct PersonPose {
  Vec3 position;           ///< point on the floor between the feet
  double yaw_rad = 0;      ///< heading: 0 faces +Z (away from the camera), pi faces the camera
  double gait_phase = 0;   ///< radians; one gait cycle is 2 pi
  double gait_amount = 0;  ///< 0 standing still .. 1 full walking stride
  ArmPose arms = ArmPose::hanging;
  bool present = false;  ///< false: not in the room in this frame
};

/// A random body: height uniform in 1.5-1.95 m, build and clothing colours.
PersonBody random_body(Rng& rng);

/// Appends the capsules of `body` in `pose` to `shapes`, owned by `track`.
void add_person_shapes(const PersonBody& body, const PersonPose& pose, int track, std::vector<Shape>& shapes);

}  // namespace rdsf::synth
