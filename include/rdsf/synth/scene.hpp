#pragma once
// What the generator renders, in world coordinates (metres): X to the right, Y up from the floor, Z forward
// along the floor (the room's long axis). The camera stands at (x, height, z), turned by yaw about Y (0
// looks along +Z, positive turns towards +X: the room's walls then appear at an angle), tilted down by
// pitch and rolled by roll about its optical axis; a moving camera (a robot driving) has a pose per frame.
// A room is an axis-aligned box (floor, ceiling, four walls) with windows (glass: no reading) and
// furniture; people are sets of capsules and boxes. Every solid is a Shape: a capsule (segment + radius; a
// sphere when both ends coincide) or an oriented box.
#include <opencv2/core.hpp>
#include <vector>

#include "rdsf/synth/vec3.hpp"

namespace rdsf::synth {

struct CameraPose {
  double x_m = 0;          ///< position of the optical centre on the floor plan
  double height_m = 1.2;   ///< height of the optical centre above the floor
  double z_m = 0;
  double yaw_rad = 0;      ///< heading: 0 looks along +Z, positive turns towards +X
  double pitch_rad = 0.0;  ///< downward tilt (positive looks down)
  double roll_rad = 0.0;   ///< rotation about the optical axis
};

/// The camera's axes in world coordinates: a camera point (x, y, z) (x right, y down, z forward) is the
/// world point origin + x right + y down + z forward. With h = (sin yaw, 0, cos yaw) and
/// r0 = (cos yaw, 0, -sin yaw): forward = cos(pitch) h - sin(pitch) Y, down0 = -cos(pitch) Y - sin(pitch) h,
/// right = cos(roll) r0 + sin(roll) down0, down = cos(roll) down0 - sin(roll) r0.
struct CameraAxes {
  Vec3 origin, right, down, forward;
  explicit CameraAxes(const CameraPose& pose);
  /// World point -> camera coordinates.
  Vec3 to_camera(const Vec3& world) const { return direction_to_camera(world - origin); }
  Vec3 direction_to_camera(const Vec3& w) const { return {dot(w, right), dot(w, down), dot(w, forward)}; }
};

enum class ShapeKind { capsule, box };

struct Shape {
  ShapeKind kind = ShapeKind::capsule;
  // capsule
  Vec3 a, b;
  double radius_m = 0;
  // box: centre, three orthonormal axes, half extents along them
  Vec3 centre;
  Vec3 axis[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Vec3 half_m;
  int owner = 0;                    ///< 0 = room or furniture, otherwise the track id of a person
  cv::Vec3b colour{128, 128, 128};  ///< BGR
  float dropout = 0;                ///< 0..1: how readily the material loses readings (dark, shiny)
};

Shape make_capsule(const Vec3& a, const Vec3& b, double radius_m, cv::Vec3b colour, int owner = 0,
                   float dropout = 0);
/// A box standing on its centre with the given yaw (rotation about Y, radians) and half extents.
Shape make_box(const Vec3& centre, double yaw_rad, const Vec3& half_m, cv::Vec3b colour, float dropout = 0);

/// A rectangle on one wall where the sensor gets no reading (a window, a black screen).
struct WallWindow {
  int wall = 0;                    ///< 2 left (X = left_x), 3 right (X = right_x), 4 front (Z = front_z)
  double from_m = 0, to_m = 0;     ///< along the wall (Z for side walls, X for the front wall)
  double bottom_m = 0, top_m = 0;  ///< height range
};

/// Floor area taken by furniture (for people to walk around): a rectangle with yaw.
struct Footprint {
  double x = 0, z = 0, half_x = 0, half_z = 0, yaw_rad = 0;
  bool contains(double px, double pz, double margin_m) const;
};

/// Surfaces of the room, as the renderer's surface index.
enum RoomSurface : int {
  surface_floor = 0,
  surface_ceiling = 1,
  surface_left = 2,
  surface_right = 3,
  surface_front = 4,
  surface_back = 5,
  surface_window = 6,
  first_shape_surface = 8,  ///< shape i of the scene is surface first_shape_surface + i
};

/// A chair a person can sit on: the seat's centre on the floor plan, its top height and the way it faces.
struct Seat {
  double x = 0, z = 0, height_m = 0.45, yaw_rad = 0;
};

struct Room {
  const char* kind = "room";  ///< "room", "corridor" or "open-plan" (room_generator.hpp)
  double left_x = -3, right_x = 3, front_z = 6, back_z = -0.5, ceiling_y = 2.7;
  cv::Vec3b floor_colour{90, 110, 130}, wall_colour{200, 205, 210}, ceiling_colour{230, 230, 230};
  float floor_dropout = 0.05f, wall_dropout = 0.02f;
  std::vector<WallWindow> windows;
  std::vector<Shape> furniture;
  std::vector<Footprint> footprints;
  std::vector<Seat> seats;  ///< chairs free to sit on (facing into the room)
  /// True when (x, z) is on the floor, at least margin_m from walls and furniture.
  bool walkable(double x, double z, double margin_m) const;
};

/// One frame's scene: the room, the camera and every solid (furniture first, then people).
struct Scene {
  Room room;
  CameraPose camera;
  std::vector<Shape> shapes;
};

}  // namespace rdsf::synth
