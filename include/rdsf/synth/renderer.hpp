#pragma once
// Renders the ideal (noise-free) depth of a scene through a pinhole camera at any pose (CameraAxes): the
// room box by a closed-form ray/plane test per pixel, then every shape with a z-buffer, testing only the pixels inside the shape's
// projected bounding box (ray/capsule and ray/box intersections). Depth is the camera's z in metres (the
// distance along the optical axis, as a Kinect reports it). Also knows which surface each pixel shows, the
// cosine of the viewing angle on room surfaces, and can shade a colour image of the same view.
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "rdsf/frame/camera_model.hpp"
#include "rdsf/synth/random.hpp"
#include "rdsf/synth/scene.hpp"

namespace rdsf::synth {

/// A shape moved into camera coordinates (x right, y down, z forward), with its image bounding box.
struct CameraShape {
  ShapeKind kind = ShapeKind::capsule;
  Vec3 a, b;  ///< capsule ends
  double radius_m = 0;
  Vec3 centre;
  Vec3 axis[3];
  Vec3 half_m;
  cv::Rect bounds;       ///< pixels that may show the shape (unclipped)
  double min_z_m = 0;    ///< nearest camera z of its bounding box
  bool visible = false;  ///< false when entirely behind the camera
};

struct RenderBuffers {
  cv::Mat1f depth_m;    ///< camera z in metres of the nearest surface
  cv::Mat1w surface;    ///< RoomSurface, or first_shape_surface + index into Scene::shapes
  cv::Mat1f incidence;  ///< |cos| of the angle between the view ray and the surface normal (room surfaces)
  std::vector<CameraShape> shapes;  ///< Scene::shapes in camera coordinates
};

class Renderer {
 public:
  explicit Renderer(const CameraModel& camera);
  const CameraModel& camera() const { return camera_; }

  void render(const Scene& scene, RenderBuffers& out) const;

  /// Pixels covered by the listed shapes of `buffers` (as rendered from `scene`) when nothing hides them,
  /// counted on the image extended by margin_px on every side (so parts outside the frame count too).
  /// With step_px > 1, every step_px-th pixel of every step_px-th row is tested (the count is scaled).
  long long silhouette_area(const RenderBuffers& buffers, const std::vector<int>& shape_indices,
                            int margin_px, int step_px = 1) const;

  /// A colour image of the rendered view: each surface's colour, shaded by its angle to the camera, with
  /// a little pixel noise from `rng`.
  cv::Mat3b shade(const Scene& scene, const RenderBuffers& buffers, Rng& rng) const;

 private:
  CameraShape to_camera(const CameraAxes& axes, const Shape& shape) const;
  /// render()'s steps: 1. the room box (and its windows) at every pixel; 2. the shapes over it.
  void render_room(const CameraAxes& axes, const Room& room, RenderBuffers& out) const;
  void render_shapes(const CameraAxes& axes, const std::vector<Shape>& shapes, RenderBuffers& out) const;

  CameraModel camera_;
  std::vector<double> ray_x_;  ///< (u - cx) / fx per column
  std::vector<double> ray_y_;  ///< (v - cy) / fy per row
};

/// Camera z of the first hit of the ray (ray_x, ray_y, 1) from the origin with the shape, or -1.
double intersect(const CameraShape& shape, double ray_x, double ray_y);

}  // namespace rdsf::synth
