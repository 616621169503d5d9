#include "synth/room_generator.hpp"

#include <algorithm>
#include <cmath>

namespace rdsf::synth {
namespace {

constexpr double pi = 3.14159265358979323846;

cv::Vec3b grey(Rng& rng, int low, int high) {
  const int v = rng.integer(low, high);
  return {static_cast<unsigned char>(v), static_cast<unsigned char>(v), static_cast<unsigned char>(v)};
}

cv::Vec3b tint(Rng& rng, int low, int high) {
  return {static_cast<unsigned char>(rng.integer(low, high)),
          static_cast<unsigned char>(rng.integer(low, high)),
          static_cast<unsigned char>(rng.integer(low, high))};
}

struct Placement {
  double x = 0, z = 0, yaw = 0;
};

/// Finds a free floor spot for a footprint of the given half extents; against a wall when asked.
bool place(Rng& rng, Room& room, double half_x, double half_z, bool against_wall, Placement& out) {
  for (int attempt = 0; attempt < 40; ++attempt) {
    Placement p;
    if (against_wall) {
      const int wall = rng.integer(0, 2);
      if (wall == 0) {  // left wall, facing +X
        p.yaw = pi / 2;
        p.x = room.left_x + half_z + 0.02;
        p.z = rng.uniform(1.0, room.front_z - half_x - 0.05);
      } else if (wall == 1) {
        p.yaw = -pi / 2;
        p.x = room.right_x - half_z - 0.02;
        p.z = rng.uniform(1.0, room.front_z - half_x - 0.05);
      } else {  // front wall, facing the camera
        p.yaw = pi;
        p.z = room.front_z - half_z - 0.02;
        p.x = rng.uniform(room.left_x + half_x + 0.05, room.right_x - half_x - 0.05);
      }
    } else {
      p.yaw = rng.uniform(-pi, pi);
      const double r = std::max(half_x, half_z);
      p.x = rng.uniform(room.left_x + r + 0.1, room.right_x - r - 0.1);
      p.z = rng.uniform(1.2 + r, std::max(1.3 + r, room.front_z - r - 0.1));
    }
    if (p.z + 0.0 > room.front_z || p.x < room.left_x || p.x > room.right_x) continue;
    const double c = std::cos(p.yaw), n = std::sin(p.yaw);
    bool free = true;
    // corners and centre must be free of other furniture
    for (int i = -1; i <= 1 && free; ++i) {
      for (int j = -1; j <= 1 && free; ++j) {
        const double lx = i * half_x, lz = j * half_z;
        const double x = p.x + lx * c + lz * n, z = p.z - lx * n + lz * c;
        for (const Footprint& f : room.footprints) {
          if (f.contains(x, z, 0.05)) free = false;
        }
      }
    }
    if (!free) continue;
    room.footprints.push_back({p.x, p.z, half_x, half_z, p.yaw});
    out = p;
    return true;
  }
  return false;
}

/// World position of a point given in the piece's own frame (x right, y up, z forward).
Vec3 at(const Placement& p, double lx, double y, double lz) {
  const double c = std::cos(p.yaw), n = std::sin(p.yaw);
  return {p.x + lx * c + lz * n, y, p.z - lx * n + lz * c};
}

void add_table(Rng& rng, Room& room) {
  const double hx = rng.uniform(0.4, 0.9), hz = rng.uniform(0.3, 0.5), height = rng.uniform(0.68, 0.78);
  Placement p;
  if (!place(rng, room, hx, hz, rng.chance(0.4), p)) return;
  const cv::Vec3b colour = tint(rng, 60, 170);
  room.furniture.push_back(make_box(at(p, 0, height - 0.02, 0), p.yaw, {hx, 0.02, hz}, colour));
  for (int i = -1; i <= 1; i += 2) {
    for (int j = -1; j <= 1; j += 2) {
      room.furniture.push_back(make_box(at(p, i * (hx - 0.04), (height - 0.04) / 2, j * (hz - 0.04)), p.yaw,
                                        {0.025, (height - 0.04) / 2, 0.025}, colour));
    }
  }
  if (rng.chance(0.5)) {  // a monitor or a box on the table; screens are black: few readings
    const double w = rng.uniform(0.2, 0.3), h = rng.uniform(0.15, 0.25);
    room.furniture.push_back(make_box(at(p, rng.uniform(-hx + w, hx - w), height + h + 0.05, 0), p.yaw,
                                      {w, h, 0.03}, grey(rng, 10, 40), 0.6f));
  }
}

void add_chair(Rng& rng, Room& room) {
  const double h = rng.uniform(0.2, 0.25), seat = rng.uniform(0.42, 0.48), back = rng.uniform(0.35, 0.5);
  Placement p;
  if (!place(rng, room, h, h, false, p)) return;
  const cv::Vec3b colour = tint(rng, 30, 160);
  room.furniture.push_back(make_box(at(p, 0, seat, 0), p.yaw, {h, 0.03, h}, colour));
  room.furniture.push_back(
      make_box(at(p, 0, seat + back / 2, -h + 0.02), p.yaw, {h, back / 2, 0.02}, colour));
  for (int i = -1; i <= 1; i += 2) {
    for (int j = -1; j <= 1; j += 2) {
      room.furniture.push_back(
          make_box(at(p, i * (h - 0.03), seat / 2, j * (h - 0.03)), p.yaw, {0.02, seat / 2, 0.02}, colour));
    }
  }
}

void add_shelf(Rng& rng, Room& room) {
  const double hx = rng.uniform(0.3, 0.8), hz = rng.uniform(0.15, 0.22), height = rng.uniform(1.2, 2.2);
  Placement p;
  if (!place(rng, room, hx, hz, true, p)) return;
  const cv::Vec3b colour = tint(rng, 50, 200);
  // frame: sides, top, back; shelves with books (dark, patchy readings) between
  room.furniture.push_back(make_box(at(p, 0, height / 2, -hz + 0.01), p.yaw, {hx, height / 2, 0.01}, colour));
  room.furniture.push_back(
      make_box(at(p, -hx + 0.015, height / 2, 0), p.yaw, {0.015, height / 2, hz}, colour));
  room.furniture.push_back(
      make_box(at(p, hx - 0.015, height / 2, 0), p.yaw, {0.015, height / 2, hz}, colour));
  const int levels = std::max(2, static_cast<int>(height / 0.38));
  for (int k = 0; k <= levels; ++k) {
    const double y = std::min(height - 0.015, 0.015 + k * (height - 0.03) / levels);
    room.furniture.push_back(make_box(at(p, 0, y, 0), p.yaw, {hx, 0.015, hz}, colour));
    if (k < levels && rng.chance(0.7)) {
      const double fill = rng.uniform(0.3, 0.95) * hx, book_h = rng.uniform(0.15, 0.28);
      room.furniture.push_back(
          make_box(at(p, rng.uniform(-hx + fill, hx - fill), y + book_h / 2 + 0.015, rng.uniform(-0.05, 0.0)),
                   p.yaw, {fill, book_h / 2, hz * 0.8}, tint(rng, 20, 220), 0.35f));
    }
  }
}

void add_boxes(Rng& rng, Room& room) {
  const double h = rng.uniform(0.2, 0.35);
  Placement p;
  if (!place(rng, room, h, h, rng.chance(0.5), p)) return;
  const int count = rng.integer(1, 3);
  double y = 0;
  for (int k = 0; k < count; ++k) {
    const double half = h * rng.uniform(0.6, 1.0), half_y = rng.uniform(0.12, 0.3);
    room.furniture.push_back(make_box(at(p, rng.uniform(-0.05, 0.05), y + half_y, rng.uniform(-0.05, 0.05)),
                                      p.yaw + rng.uniform(-0.3, 0.3), {half, half_y, half},
                                      cv::Vec3b(static_cast<unsigned char>(rng.integer(60, 90)),
                                                static_cast<unsigned char>(rng.integer(120, 150)),
                                                static_cast<unsigned char>(rng.integer(160, 190)))));
    y += 2 * half_y;
  }
}

void add_coat_stand(Rng& rng, Room& room) {
  Placement p;
  if (!place(rng, room, 0.25, 0.25, false, p)) return;
  const double height = rng.uniform(1.65, 1.9);
  const cv::Vec3b colour = tint(rng, 20, 120);
  room.furniture.push_back(make_capsule(at(p, 0, 0.03, 0), at(p, 0, height, 0), 0.025, colour));
  for (int k = 0; k < 4; ++k) {
    const double angle = k * pi / 2 + 0.4;
    room.furniture.push_back(make_capsule(
        at(p, 0, 0.03, 0), at(p, 0.25 * std::cos(angle), 0.02, 0.25 * std::sin(angle)), 0.02, colour));
    room.furniture.push_back(make_capsule(at(p, 0, height - 0.1, 0),
                                          at(p, 0.12 * std::cos(angle), height, 0.12 * std::sin(angle)),
                                          0.015, colour));
  }
  if (rng.chance(0.6)) {  // a coat hanging from it: a soft, person-like column
    const double r = rng.uniform(0.1, 0.16);
    room.furniture.push_back(make_capsule(at(p, 0.05, height - 0.15 - r, 0.05),
                                          at(p, 0.05, height - rng.uniform(0.8, 1.1), 0.05), r,
                                          tint(rng, 20, 140)));
  }
}

void add_robot(Rng& rng, Room& room) {
  Placement p;
  const double r = rng.uniform(0.15, 0.25);
  if (!place(rng, room, r + 0.05, r + 0.05, false, p)) return;
  const double height = rng.uniform(1.0, 1.6);
  const cv::Vec3b colour = tint(rng, 120, 230);
  room.furniture.push_back(make_capsule(at(p, 0, r, 0), at(p, 0, height - r - 0.15, 0), r, colour));
  const double head = rng.uniform(0.09, 0.13);
  room.furniture.push_back(
      make_capsule(at(p, 0, height - head, 0), at(p, 0, height - head, 0), head, colour));
  room.furniture.push_back(
      make_box(at(p, 0, 0.05, 0), p.yaw, {r + 0.05, 0.05, r + 0.05}, grey(rng, 20, 60), 0.3f));
}

void add_cabinet(Rng& rng, Room& room) {
  const double hx = rng.uniform(0.4, 1.0), hz = rng.uniform(0.2, 0.45), height = rng.uniform(0.45, 1.1);
  Placement p;
  if (!place(rng, room, hx, hz, true, p)) return;
  room.furniture.push_back(
      make_box(at(p, 0, height / 2, 0), p.yaw, {hx, height / 2, hz}, tint(rng, 40, 200)));
  if (rng.chance(0.5)) {  // a television: black glass
    const double w = rng.uniform(0.35, 0.6), h = rng.uniform(0.22, 0.35);
    room.furniture.push_back(
        make_box(at(p, 0, height + h + 0.05, 0), p.yaw, {w, h, 0.03}, grey(rng, 5, 25), 0.9f));
  }
}

}  // namespace

Room generate_room(Rng& rng, const RoomParams& params, CameraPose& camera) {
  Room room;
  room.front_z = rng.chance(params.deep_room_share) ? rng.uniform(params.front_max_m, params.deep_front_max_m)
                                                    : rng.uniform(params.front_min_m, params.front_max_m);
  room.left_x = -rng.uniform(params.side_min_m, params.side_max_m);
  room.right_x = rng.uniform(params.side_min_m, params.side_max_m);
  room.back_z = -rng.uniform(0.3, 1.0);
  room.ceiling_y = rng.uniform(2.4, 3.2);
  room.floor_colour = tint(rng, 50, 170);
  room.wall_colour = tint(rng, 160, 240);
  room.ceiling_colour = grey(rng, 200, 250);
  room.floor_dropout = static_cast<float>(rng.uniform(0.0, 0.2));
  room.wall_dropout = static_cast<float>(rng.uniform(0.0, 0.05));
  camera.height_m = rng.uniform(params.camera_height_min_m, params.camera_height_max_m);
  camera.pitch_rad = rng.uniform(params.pitch_min_deg, params.pitch_max_deg) * pi / 180.0;

  const int windows = rng.integer(0, 2);
  for (int k = 0; k < windows; ++k) {
    WallWindow w;
    w.wall = rng.integer(2, 4);
    const double width = rng.uniform(0.8, 2.0);
    const double along_low = w.wall == 4 ? room.left_x : 0.5;
    const double along_high = w.wall == 4 ? room.right_x : room.front_z;
    if (along_high - along_low < width + 0.2) continue;
    w.from_m = rng.uniform(along_low + 0.1, along_high - width - 0.1);
    w.to_m = w.from_m + width;
    w.bottom_m = rng.uniform(0.8, 1.1);
    w.top_m = std::min(room.ceiling_y - 0.2, w.bottom_m + rng.uniform(0.9, 1.5));
    room.windows.push_back(w);
  }

  const int pieces = rng.integer(params.furniture_min, params.furniture_max);
  for (int k = 0; k < pieces; ++k) {
    const double pick = rng.uniform();
    if (pick < 0.18) {
      add_table(rng, room);
    } else if (pick < 0.40) {
      add_chair(rng, room);
    } else if (pick < 0.55) {
      add_shelf(rng, room);
    } else if (pick < 0.70) {
      add_boxes(rng, room);
    } else if (pick < 0.80) {
      add_coat_stand(rng, room);
    } else if (pick < 0.88) {
      add_robot(rng, room);
    } else {
      add_cabinet(rng, room);
    }
  }
  // materials: dark, glossy or finely structured surfaces lose some readings in patches
  for (Shape& shape : room.furniture) {
    shape.dropout = std::max(shape.dropout, static_cast<float>(rng.uniform(0.0, 0.3)));
  }
  return room;
}

}  // namespace rdsf::synth
