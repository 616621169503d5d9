#include "rdsf/synth/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rdsf::synth {
namespace {

constexpr double near_m = 0.05;

double capsule_hit(const CameraShape& s, const Vec3& d) {
  // Ray origin O = 0, direction d (not normalised; its z is 1, so t is the camera z).
  const Vec3 ba = s.b - s.a;
  const Vec3 oa = Vec3{0, 0, 0} - s.a;
  const double baba = dot(ba, ba);
  const double dd = dot(d, d);
  const double r2 = s.radius_m * s.radius_m;
  if (baba > 1e-12) {
    const double bard = dot(ba, d), baoa = dot(ba, oa), rdoa = dot(d, oa), oaoa = dot(oa, oa);
    const double qa = baba * dd - bard * bard;
    const double qb = baba * rdoa - baoa * bard;
    const double qc = baba * oaoa - baoa * baoa - r2 * baba;
    const double disc = qb * qb - qa * qc;
    if (disc < 0) return -1;
    if (qa > 1e-12) {
      const double t = (-qb - std::sqrt(disc)) / qa;
      const double y = baoa + t * bard;
      if (y > 0 && y < baba) return t > near_m ? t : -1;
    }
    // an end cap
    const double y = baoa + ((qa > 1e-12) ? (-qb - std::sqrt(disc)) / qa : 0.0) * bard;
    const Vec3 oc = y <= 0 ? oa : Vec3{0, 0, 0} - s.b;
    const double b = dot(d, oc), c = dot(oc, oc) - r2;
    const double h = b * b - dd * c;
    if (h < 0) return -1;
    const double t = (-b - std::sqrt(h)) / dd;
    return t > near_m ? t : -1;
  }
  const double b = dot(d, oa), c = dot(oa, oa) - r2;
  const double h = b * b - dd * c;
  if (h < 0) return -1;
  const double t = (-b - std::sqrt(h)) / dd;
  return t > near_m ? t : -1;
}

double box_hit(const CameraShape& s, const Vec3& d) {
  double t_near = -std::numeric_limits<double>::infinity(), t_far = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double o = -dot(s.centre, s.axis[i]);
    const double dir = dot(d, s.axis[i]);
    const double h = i == 0 ? s.half_m.x : (i == 1 ? s.half_m.y : s.half_m.z);
    if (std::abs(dir) < 1e-12) {
      if (o < -h || o > h) return -1;
      continue;
    }
    double t1 = (-h - o) / dir, t2 = (h - o) / dir;
    if (t1 > t2) std::swap(t1, t2);
    t_near = std::max(t_near, t1);
    t_far = std::min(t_far, t2);
    if (t_near > t_far) return -1;
  }
  if (t_far < near_m) return -1;
  return t_near > near_m ? t_near : -1;
}

}  // namespace

double intersect(const CameraShape& shape, double ray_x, double ray_y) {
  const Vec3 d{ray_x, ray_y, 1.0};
  return shape.kind == ShapeKind::capsule ? capsule_hit(shape, d) : box_hit(shape, d);
}

Renderer::Renderer(const CameraModel& camera) : camera_(camera) {
  ray_x_.resize(static_cast<std::size_t>(camera.width_px));
  ray_y_.resize(static_cast<std::size_t>(camera.height_px));
  for (int u = 0; u < camera.width_px; ++u)
    ray_x_[static_cast<std::size_t>(u)] = (u - camera.cx_px) / camera.fx_px;
  for (int v = 0; v < camera.height_px; ++v)
    ray_y_[static_cast<std::size_t>(v)] = (v - camera.cy_px) / camera.fy_px;
}

CameraShape Renderer::to_camera(const CameraAxes& axes, const Shape& shape) const {
  CameraShape s;
  s.kind = shape.kind;
  Vec3 corner_min, corner_max;
  if (shape.kind == ShapeKind::capsule) {
    s.a = axes.to_camera(shape.a);
    s.b = axes.to_camera(shape.b);
    s.radius_m = shape.radius_m;
    const double r = shape.radius_m;
    corner_min = {std::min(s.a.x, s.b.x) - r, std::min(s.a.y, s.b.y) - r, std::min(s.a.z, s.b.z) - r};
    corner_max = {std::max(s.a.x, s.b.x) + r, std::max(s.a.y, s.b.y) + r, std::max(s.a.z, s.b.z) + r};
  } else {
    s.centre = axes.to_camera(shape.centre);
    for (int i = 0; i < 3; ++i) s.axis[i] = axes.direction_to_camera(shape.axis[i]);
    s.half_m = shape.half_m;
    const Vec3 extent{std::abs(s.axis[0].x) * s.half_m.x + std::abs(s.axis[1].x) * s.half_m.y +
                          std::abs(s.axis[2].x) * s.half_m.z,
                      std::abs(s.axis[0].y) * s.half_m.x + std::abs(s.axis[1].y) * s.half_m.y +
                          std::abs(s.axis[2].y) * s.half_m.z,
                      std::abs(s.axis[0].z) * s.half_m.x + std::abs(s.axis[1].z) * s.half_m.y +
                          std::abs(s.axis[2].z) * s.half_m.z};
    corner_min = s.centre - extent;
    corner_max = s.centre + extent;
  }
  s.min_z_m = corner_min.z;
  if (corner_max.z <= near_m) return s;  // behind the camera
  s.visible = true;
  if (corner_min.z <= near_m) {
    s.bounds = {-100000, -100000, 200000, 200000};
    return s;
  }
  double u0 = 1e18, u1 = -1e18, v0 = 1e18, v1 = -1e18;
  for (int k = 0; k < 8; ++k) {
    const double x = (k & 1) ? corner_max.x : corner_min.x;
    const double y = (k & 2) ? corner_max.y : corner_min.y;
    const double z = (k & 4) ? corner_max.z : corner_min.z;
    const double u = camera_.fx_px * x / z + camera_.cx_px, v = camera_.fy_px * y / z + camera_.cy_px;
    u0 = std::min(u0, u);
    u1 = std::max(u1, u);
    v0 = std::min(v0, v);
    v1 = std::max(v1, v);
  }
  u0 = std::max(u0, -100000.0);
  v0 = std::max(v0, -100000.0);
  u1 = std::min(u1, 100000.0);
  v1 = std::min(v1, 100000.0);
  const int x0 = static_cast<int>(std::floor(u0)) - 1, y0 = static_cast<int>(std::floor(v0)) - 1;
  s.bounds = {x0, y0, static_cast<int>(std::ceil(u1)) + 2 - x0, static_cast<int>(std::ceil(v1)) + 2 - y0};
  return s;
}

namespace {

struct RoomHit {
  double t = 1e9;       // camera z of the hit
  int surface = surface_floor;
  double cosine = 1;    // of the angle between the ray and the surface's normal
};

// Where the ray of world direction (wx, wy, wz) from `o` leaves the (convex) room box: through the nearest
// plane ahead of it; a window of the wall it hits is a surface of its own.
RoomHit room_hit(const Room& room, const Vec3& o, double wx, double wy, double wz) {
  double t = 1e9;
  int s = surface_floor;
  if (wy < 0) {
    t = -o.y / wy;
  } else if (wy > 0) {
    t = (room.ceiling_y - o.y) / wy;
    s = surface_ceiling;
  }
  if (wz > 0) {
    const double tz = (room.front_z - o.z) / wz;
    if (tz < t) {
      t = tz;
      s = surface_front;
    }
  } else if (wz < 0) {
    const double tz = (room.back_z - o.z) / wz;
    if (tz < t) {
      t = tz;
      s = surface_back;
    }
  }
  if (wx < 0) {
    const double tx = (room.left_x - o.x) / wx;
    if (tx < t) {
      t = tx;
      s = surface_left;
    }
  } else if (wx > 0) {
    const double tx = (room.right_x - o.x) / wx;
    if (tx < t) {
      t = tx;
      s = surface_right;
    }
  }
  const double norm = std::sqrt(wx * wx + wy * wy + wz * wz);
  double cosine = 1;
  if (s == surface_floor || s == surface_ceiling) {
    cosine = std::abs(wy) / norm;
  } else if (s == surface_left || s == surface_right) {
    cosine = std::abs(wx) / norm;
  } else {
    cosine = std::abs(wz) / norm;
  }
  if (!room.windows.empty() && (s == surface_left || s == surface_right || s == surface_front)) {
    const double hx = o.x + t * wx, hy = o.y + t * wy, hz = o.z + t * wz;
    for (const WallWindow& w : room.windows) {
      if (w.wall != s) continue;
      const double along = s == surface_front ? hx : hz;
      if (along >= w.from_m && along <= w.to_m && hy >= w.bottom_m && hy <= w.top_m) s = surface_window;
    }
  }
  return {t, s, cosine};
}

}  // namespace

void Renderer::render(const Scene& scene, RenderBuffers& out) const {
  out.depth_m.create(camera_.height_px, camera_.width_px);
  out.surface.create(camera_.height_px, camera_.width_px);
  out.incidence.create(camera_.height_px, camera_.width_px);
  const CameraAxes axes(scene.camera);
  render_room(axes, scene.room, out);
  render_shapes(axes, scene.shapes, out);
}

void Renderer::render_room(const CameraAxes& axes, const Room& room, RenderBuffers& out) const {
  // The ray of pixel (u, v) has the world direction right * ray_x + down * ray_y + forward (camera z = 1,
  // so the parameter t of the hit is the camera z).
  for (int v = 0; v < camera_.height_px; ++v) {
    const Vec3 row = axes.down * ray_y_[static_cast<std::size_t>(v)] + axes.forward;
    float* depth = out.depth_m.ptr<float>(v);
    std::uint16_t* surface = out.surface.ptr<std::uint16_t>(v);
    float* incidence = out.incidence.ptr<float>(v);
    for (int u = 0; u < camera_.width_px; ++u) {
      const double ru = ray_x_[static_cast<std::size_t>(u)];
      const RoomHit hit = room_hit(room, axes.origin, row.x + axes.right.x * ru, row.y + axes.right.y * ru,
                                   row.z + axes.right.z * ru);
      depth[u] = static_cast<float>(hit.t);
      surface[u] = static_cast<std::uint16_t>(hit.surface);
      incidence[u] = static_cast<float>(hit.cosine);
    }
  }
}

void Renderer::render_shapes(const CameraAxes& axes, const std::vector<Shape>& shapes, RenderBuffers& out) const {
  // z-buffered in list order (a shape listed later wins only when strictly nearer); a pixel already nearer
  // than a shape's bounding box cannot show it, which skips the ray tests of hidden parts
  out.shapes.clear();
  out.shapes.reserve(shapes.size());
  const cv::Rect image(0, 0, camera_.width_px, camera_.height_px);
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    out.shapes.push_back(to_camera(axes, shapes[i]));
    const CameraShape& s = out.shapes.back();
    if (!s.visible) continue;
    const cv::Rect area = s.bounds & image;
    const auto id = static_cast<std::uint16_t>(first_shape_surface + i);
    const float nearest = static_cast<float>(s.min_z_m);
    for (int v = area.y; v < area.y + area.height; ++v) {
      float* depth = out.depth_m.ptr<float>(v);
      std::uint16_t* surface = out.surface.ptr<std::uint16_t>(v);
      float* incidence = out.incidence.ptr<float>(v);
      const double b = ray_y_[static_cast<std::size_t>(v)];
      for (int u = area.x; u < area.x + area.width; ++u) {
        if (depth[u] < nearest) continue;
        const double t = intersect(s, ray_x_[static_cast<std::size_t>(u)], b);
        if (t > 0 && t < depth[u]) {
          depth[u] = static_cast<float>(t);
          surface[u] = id;
          incidence[u] = 1.0f;
        }
      }
    }
  }
}

long long Renderer::silhouette_area(const RenderBuffers& buffers, const std::vector<int>& shape_indices,
                                    int margin_px, int step_px) const {
  step_px = std::max(1, step_px);
  const cv::Rect canvas(-margin_px, -margin_px, camera_.width_px + 2 * margin_px,
                        camera_.height_px + 2 * margin_px);
  cv::Rect all;
  for (int i : shape_indices) {
    const CameraShape& s = buffers.shapes[static_cast<std::size_t>(i)];
    if (s.visible) all |= (s.bounds & canvas);
  }
  if (all.empty()) return 0;
  std::vector<unsigned char> mask(static_cast<std::size_t>(all.area()), 0);
  for (int i : shape_indices) {
    const CameraShape& s = buffers.shapes[static_cast<std::size_t>(i)];
    if (!s.visible) continue;
    const cv::Rect area = s.bounds & all;
    // sample on a grid anchored at the canvas corner, so every shape tests the same pixels
    auto first_on_grid = [&](int from, int origin) {
      return origin + ((from - origin + step_px - 1) / step_px) * step_px;
    };
    for (int v = first_on_grid(area.y, all.y); v < area.y + area.height; v += step_px) {
      const double b = (v - camera_.cy_px) / camera_.fy_px;
      unsigned char* row =
          mask.data() + static_cast<std::size_t>(v - all.y) * static_cast<std::size_t>(all.width);
      for (int u = first_on_grid(area.x, all.x); u < area.x + area.width; u += step_px) {
        unsigned char& m = row[u - all.x];
        if (m) continue;
        if (intersect(s, (u - camera_.cx_px) / camera_.fx_px, b) > 0) m = 1;
      }
    }
  }
  long long count = 0;
  for (unsigned char m : mask) count += m;
  return count * step_px * step_px;
}

cv::Mat3b Renderer::shade(const Scene& scene, const RenderBuffers& buffers, Rng& rng) const {
  const int width = camera_.width_px, height = camera_.height_px;
  cv::Mat3b bgr(height, width);
  const Room& room = scene.room;
  const cv::Vec3b room_colours[7] = {room.floor_colour,      room.ceiling_colour, room.wall_colour,
                                     room.wall_colour,       room.wall_colour,    room.wall_colour,
                                     cv::Vec3b(150, 120, 90)};
  for (int v = 0; v < height; ++v) {
    const float* depth = buffers.depth_m.ptr<float>(v);
    const std::uint16_t* surface = buffers.surface.ptr<std::uint16_t>(v);
    const float* incidence = buffers.incidence.ptr<float>(v);
    cv::Vec3b* out = bgr.ptr<cv::Vec3b>(v);
    const double b = ray_y_[static_cast<std::size_t>(v)];
    std::uint64_t bits = 0;
    for (int u = 0; u < width; ++u) {
      const int s = surface[u];
      double cosine = 1;
      cv::Vec3b base;
      if (s < first_shape_surface) {
        base = room_colours[std::min(s, 6)];
        cosine = incidence[u];
      } else {
        const std::size_t index = static_cast<std::size_t>(s - first_shape_surface);
        const CameraShape& cs = buffers.shapes[index];
        base = scene.shapes[index].colour;
        const Vec3 d{ray_x_[static_cast<std::size_t>(u)], b, 1.0};
        const Vec3 p = d * static_cast<double>(depth[u]);
        Vec3 normal;
        if (cs.kind == ShapeKind::capsule) {
          const Vec3 ba = cs.b - cs.a;
          const double baba = dot(ba, ba);
          const double h = baba > 1e-12 ? std::clamp(dot(p - cs.a, ba) / baba, 0.0, 1.0) : 0.0;
          normal = normalised(p - (cs.a + ba * h));
        } else {
          const Vec3 local = p - cs.centre;
          double best = -1;
          for (int i = 0; i < 3; ++i) {
            const double half = i == 0 ? cs.half_m.x : (i == 1 ? cs.half_m.y : cs.half_m.z);
            const double k = std::abs(dot(local, cs.axis[i])) / std::max(half, 1e-6);
            if (k > best) {
              best = k;
              normal = cs.axis[i];
            }
          }
        }
        cosine = std::abs(dot(normal, d)) / length(d);
      }
      if ((u & 7) == 0) bits = rng.next();
      const int noise = static_cast<int>((bits >> ((u & 7) * 8)) & 15) - 8;
      const double light = 0.35 + 0.65 * cosine;
      for (int c = 0; c < 3; ++c) {
        out[u][c] = cv::saturate_cast<unsigned char>(base[c] * light + noise);
      }
    }
  }
  return bgr;
}

}  // namespace rdsf::synth
