#pragma once
// An articulated person made of capsules and boxes: head with hair, neck, torso (two capsules side by side,
// so it is wider than deep), pelvis, upper and lower arms, upper and lower legs and feet, with proportions
// of a body scaled to its height (children to tall adults, slim to heavy). Clothes and things carried are
// more shapes of the same person: a long coat, a skirt or a dress, loose clothes, long hair or a bun, a
// backpack, a shoulder bag, a handbag, a box or a tray held in both hands. Forward kinematics turn a pose
// (position, heading, gait phase, posture: standing, sitting on a seat or bending; arm pose) into shapes in
// world coordinates, all owned by the person's track (so the ground-truth box covers bags and boxes, as
// the real boxes from the middleware's user mask do).
#include <opencv2/core.hpp>
#include <vector>

#include "rdsf/synth/random.hpp"
#include "rdsf/synth/scene.hpp"

namespace rdsf::synth {

enum class HairStyle { short_hair, long_hair, bun };
enum class Garment { trousers, skirt, dress };
enum class Carried { nothing, backpack, shoulder_bag, handbag, box, tray };

struct PersonBody {
  double height_m = 1.75;  ///< children 1.0-1.45 m, adults 1.5-2.0 m (without variety: 1.5-1.95 m)
  double build = 1.0;      ///< girth factor on every radius, 0.8-1.45 (without variety: 0.85-1.2)
  double belly = 0;        ///< extra depth of the lower torso, 0..1 (heavy people)
  cv::Vec3b shirt{90, 60, 40}, trousers{60, 50, 40}, skin{120, 150, 200}, hair{20, 30, 40};  ///< BGR
  float hair_dropout = 0.2f;  ///< dark hair loses readings
  HairStyle hair_style = HairStyle::short_hair;
  Garment garment = Garment::trousers;
  bool coat = false;       ///< a long coat down to the knees over everything
  double looseness = 1.0;  ///< loose clothes: factor 1-1.3 on torso and sleeve radii
  Carried carried = Carried::nothing;
  cv::Vec3b bag{40, 40, 40};
  Vec3 bag_half_m{0.15, 0.2, 0.08};  ///< size of the bag, box or tray (half extents)
};

enum class ArmPose {
  hanging,   ///< arms by the body (they swing when walking)
  phone,     ///< one hand at the ear
  holding,   ///< both forearms forward, as when carrying something
  akimbo,    ///< hands on the hips, elbows out
  raised,    ///< both arms up
  out,       ///< both arms stretched out to the sides
  crossed,   ///< forearms crossed before the chest
  pockets,   ///< hands in the trouser pockets
  pointing,  ///< one arm stretched forward
  waving,    ///< one arm up
};

enum class Posture { standing, sitting, bending };

struct PersonPose {
  Vec3 position;           ///< point on the floor between the feet (sitting: below the seat's centre)
  double yaw_rad = 0;      ///< heading: 0 faces +Z (away from the camera), pi faces the camera
  double gait_phase = 0;   ///< radians; one gait cycle is 2 pi
  double gait_amount = 0;  ///< 0 standing still .. 1 full walking stride
  ArmPose arms = ArmPose::hanging;
  Posture posture = Posture::standing;
  double seat_height_m = 0.45;  ///< top of the seat (sitting)
  double bend_rad = 0;          ///< forward lean of the upper body about the hips (bending: up to 1.2)
  bool present = false;         ///< false: not in the room in this frame
};

struct BodyParams {
  bool varied_bodies = true;  ///< children and tall, slim and heavy people (off: adults 1.5-1.95 m)
  bool outfits = true;        ///< coats, skirts, loose clothes, hair styles, bags and carried things
  double child_share = 0.12;  ///< share of children (1.0-1.45 m) with varied bodies
};

/// A random body: height, build and clothing.
PersonBody random_body(Rng& rng, const BodyParams& params = {});

/// Height above the floor of the middle of the torso in `pose` (for the distance to the camera).
double torso_height_m(const PersonBody& body, const PersonPose& pose);

/// Appends the shapes of `body` in `pose` to `shapes`, owned by `track`.
void add_person_shapes(const PersonBody& body, const PersonPose& pose, int track, std::vector<Shape>& shapes);

}  // namespace rdsf::synth
