#include "rdsf/synth/room_generator.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "rdsf/synth/angle.hpp"

namespace rdsf::synth {
namespace {

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

void chair_at(Rng& rng, Room& room, const Placement& p, double h, double seat, double back, cv::Vec3b colour,
              bool jackets) {
  room.furniture.push_back(make_box(at(p, 0, seat, 0), p.yaw, {h, 0.03, h}, colour));
  room.furniture.push_back(
      make_box(at(p, 0, seat + back / 2, -h + 0.02), p.yaw, {h, back / 2, 0.02}, colour));
  for (int i = -1; i <= 1; i += 2) {
    for (int j = -1; j <= 1; j += 2) {
      room.furniture.push_back(
          make_box(at(p, i * (h - 0.03), seat / 2, j * (h - 0.03)), p.yaw, {0.02, seat / 2, 0.02}, colour));
    }
  }
  room.seats.push_back({p.x, p.z, seat + 0.03, p.yaw});
  if (jackets && rng.chance(0.12)) {  // a jacket hung over the back
    room.furniture.push_back(make_capsule(at(p, -0.8 * h, seat + back - 0.05, -h), at(p, 0.8 * h, seat + back - 0.05, -h),
                                          0.06, tint(rng, 20, 120)));
    room.furniture.push_back(make_box(at(p, 0, seat + back / 2, -h - 0.03), p.yaw, {0.8 * h, back / 2, 0.03},
                                      tint(rng, 20, 120)));
  }
}

void add_chair(Rng& rng, Room& room, bool jackets) {
  const double h = rng.uniform(0.2, 0.25), seat = rng.uniform(0.42, 0.48), back = rng.uniform(0.35, 0.5);
  Placement p;
  if (!place(rng, room, h, h, false, p)) return;
  chair_at(rng, room, p, h, seat, back, tint(rng, 30, 160), jackets);
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


// ---- clutter of real labs and offices (RoomParams::clutter) ----

/// A potted plant: a pot, a stem and a crown of leafy balls; tall ones are as tall as a person.
void add_plant(Rng& rng, Room& room) {
  const double pot_r = rng.uniform(0.1, 0.22), pot_h = rng.uniform(0.2, 0.45);
  Placement p;
  if (!place(rng, room, pot_r + 0.1, pot_r + 0.1, rng.chance(0.5), p)) return;
  const double height = rng.chance(0.5) ? rng.uniform(1.2, 1.9) : rng.uniform(0.5, 1.2);
  room.furniture.push_back(make_capsule(at(p, 0, pot_r * 0.5, 0), at(p, 0, pot_h - pot_r * 0.5, 0), pot_r,
                                        tint(rng, 40, 180)));
  const cv::Vec3b leaves = {static_cast<unsigned char>(rng.integer(20, 70)), static_cast<unsigned char>(rng.integer(70, 150)),
                            static_cast<unsigned char>(rng.integer(30, 80))};
  room.furniture.push_back(make_capsule(at(p, 0, pot_h, 0), at(p, 0, height * 0.8, 0), 0.015, leaves));
  const int balls = rng.integer(4, 10);
  const double spread = rng.uniform(0.15, 0.35);
  for (int k = 0; k < balls; ++k) {
    const double y = pot_h + (height - pot_h) * rng.uniform(0.35, 0.95);
    const double r = rng.uniform(0.06, 0.18) * (0.6 + height / 3.0);
    const Vec3 centre = at(p, rng.uniform(-spread, spread), y, rng.uniform(-spread, spread));
    room.furniture.push_back(make_capsule(centre, centre + Vec3{rng.uniform(-0.1, 0.1), rng.uniform(0.0, 0.15), 0}, r,
                                          leaves, static_cast<float>(rng.uniform(0.25, 0.55))));
  }
}

/// A floor lamp: a round foot, a pole and a shade.
void add_lamp(Rng& rng, Room& room) {
  Placement p;
  if (!place(rng, room, 0.18, 0.18, rng.chance(0.6), p)) return;
  const double height = rng.uniform(1.3, 1.85);
  const cv::Vec3b colour = tint(rng, 30, 220);
  room.furniture.push_back(make_capsule(at(p, -0.1, 0.02, 0), at(p, 0.1, 0.02, 0), 0.03, colour));
  room.furniture.push_back(make_capsule(at(p, 0, 0.03, 0), at(p, 0, height - 0.1, 0), 0.015, colour));
  const double shade = rng.uniform(0.13, 0.24);
  room.furniture.push_back(make_capsule(at(p, 0, height - 0.12, 0), at(p, 0, height, 0), shade, tint(rng, 150, 250)));
}

/// A door in a wall: a frame standing out of the wall, the leaf closed or swung open into the room.
void add_door(Rng& rng, Room& room) {
  const int wall = rng.integer(0, 2);
  const double width = rng.uniform(0.8, 1.0), height = rng.uniform(2.0, 2.15), depth = rng.uniform(0.03, 0.1);
  Placement p;
  // the door's own frame: x along the wall, z out of the wall into the room
  if (wall == 2) {
    if (room.right_x - room.left_x < width + 0.6) return;
    p = {rng.uniform(room.left_x + width, room.right_x - width), room.front_z, pi};
  } else {
    if (room.front_z < 2.5) return;
    const double z = rng.uniform(1.0, room.front_z - width - 0.2);
    p = wall == 0 ? Placement{room.left_x, z, pi / 2} : Placement{room.right_x, z, -pi / 2};
  }
  const cv::Vec3b frame = tint(rng, 120, 240), leaf = tint(rng, 60, 220);
  for (int side = -1; side <= 1; side += 2) {
    room.furniture.push_back(make_box(at(p, side * (width / 2 + 0.04), height / 2, depth / 2), p.yaw,
                                      {0.04, height / 2, depth / 2}, frame));
  }
  room.furniture.push_back(make_box(at(p, 0, height + 0.04, depth / 2), p.yaw, {width / 2 + 0.08, 0.04, depth / 2}, frame));
  const double open = rng.chance(0.5) ? rng.uniform(0.3, 1.6) : 0.0;  // radians the leaf is swung open
  const double hinge_x = -width / 2;
  const double yaw = p.yaw - open;
  const Vec3 hinge = at(p, hinge_x, 0, 0.02);
  const Vec3 along{std::cos(yaw), 0, -std::sin(yaw)};
  const Vec3 centre = hinge + along * (width / 2) + Vec3{0, height / 2, 0};
  room.furniture.push_back(make_box(centre, yaw, {width / 2, height / 2 - 0.01, 0.02}, leaf));
  if (open > 0.2) room.footprints.push_back({centre.x, centre.z, width / 2 + 0.05, 0.1, yaw});
}

/// Chairs stacked on each other: a column as tall as a child or an adult.
void add_stacked_chairs(Rng& rng, Room& room) {
  const double h = rng.uniform(0.2, 0.24), seat = rng.uniform(0.42, 0.46), back = rng.uniform(0.35, 0.45);
  Placement p;
  if (!place(rng, room, h + 0.03, h + 0.05, rng.chance(0.6), p)) return;
  const cv::Vec3b colour = tint(rng, 30, 160);
  const int count = rng.integer(3, 8);
  for (int k = 0; k < count; ++k) {
    const double y = seat + k * 0.075;
    room.furniture.push_back(make_box(at(p, 0, y, -0.012 * k), p.yaw, {h, 0.02, h}, colour));
    room.furniture.push_back(make_box(at(p, 0, y + back / 2, -h + 0.02 - 0.012 * k), p.yaw, {h, back / 2, 0.015}, colour));
  }
  for (int i = -1; i <= 1; i += 2) {
    for (int j = -1; j <= 1; j += 2) {
      room.furniture.push_back(make_box(at(p, i * (h - 0.02), seat / 2, j * (h - 0.02)), p.yaw, {0.015, seat / 2, 0.015}, colour));
    }
  }
}

/// A coat rack: a rail on two feet with coats and bags hanging from it (the most person-like clutter).
void add_coat_rack(Rng& rng, Room& room) {
  const double half = rng.uniform(0.35, 0.7), height = rng.uniform(1.6, 1.85);
  Placement p;
  if (!place(rng, room, half, 0.25, rng.chance(0.6), p)) return;
  const cv::Vec3b metal = tint(rng, 30, 200);
  for (int side = -1; side <= 1; side += 2) {
    room.furniture.push_back(make_capsule(at(p, side * half, 0.02, -0.2), at(p, side * half, 0.02, 0.2), 0.02, metal));
    room.furniture.push_back(make_capsule(at(p, side * half, 0.02, 0), at(p, side * half, height, 0), 0.015, metal));
  }
  room.furniture.push_back(make_capsule(at(p, -half, height, 0), at(p, half, height, 0), 0.015, metal));
  const int coats = rng.integer(1, 5);
  for (int k = 0; k < coats; ++k) {
    const double x = rng.uniform(-half + 0.12, half - 0.12), length = rng.uniform(0.6, 1.15);
    const double r = rng.uniform(0.1, 0.17);
    const cv::Vec3b colour = tint(rng, 15, 150);
    room.furniture.push_back(make_capsule(at(p, x, height - 0.08 - r, rng.uniform(-0.03, 0.03)),
                                          at(p, x, height - length, rng.uniform(-0.03, 0.03)), r, colour));
    if (rng.chance(0.5)) {  // shoulders of the coat
      room.furniture.push_back(make_capsule(at(p, x - 0.17, height - 0.12, 0), at(p, x + 0.17, height - 0.12, 0), 0.06, colour));
    }
  }
}

/// A tall cupboard or locker against a wall.
void add_cupboard(Rng& rng, Room& room) {
  const double hx = rng.uniform(0.3, 0.6), hz = rng.uniform(0.2, 0.32), height = rng.uniform(1.7, 2.2);
  Placement p;
  if (!place(rng, room, hx, hz, true, p)) return;
  const cv::Vec3b colour = tint(rng, 60, 230);
  room.furniture.push_back(make_box(at(p, 0, height / 2, 0), p.yaw, {hx, height / 2, hz}, colour));
  if (rng.chance(0.5)) {  // things on top
    room.furniture.push_back(make_box(at(p, rng.uniform(-hx / 2, hx / 2), height + 0.12, 0), p.yaw + rng.uniform(-0.3, 0.3),
                                      {rng.uniform(0.1, 0.25), 0.12, rng.uniform(0.1, 0.2)}, tint(rng, 60, 190)));
  }
}

/// An office desk with one or two monitors, a computer under it and its chair (often pulled out).
void add_desk(Rng& rng, Room& room) {
  const double hx = rng.uniform(0.55, 0.85), hz = rng.uniform(0.35, 0.45), height = rng.uniform(0.7, 0.76);
  Placement p;
  if (!place(rng, room, hx, hz + 0.35, rng.chance(0.5), p)) return;
  const cv::Vec3b colour = tint(rng, 80, 220);
  room.furniture.push_back(make_box(at(p, 0, height - 0.015, 0.15), p.yaw, {hx, 0.015, hz}, colour));
  for (int side = -1; side <= 1; side += 2) {
    room.furniture.push_back(make_box(at(p, side * (hx - 0.02), (height - 0.03) / 2, 0.15), p.yaw, {0.02, (height - 0.03) / 2, hz - 0.02}, colour));
  }
  const int monitors = rng.integer(1, 2);
  for (int k = 0; k < monitors; ++k) {
    const double w = rng.uniform(0.22, 0.3), mh = rng.uniform(0.15, 0.21);
    const double x = monitors == 1 ? rng.uniform(-0.2, 0.2) : (k == 0 ? -1 : 1) * (w + 0.02);
    const double twist = rng.uniform(-0.3, 0.3) + (monitors == 2 ? (k == 0 ? 0.15 : -0.15) : 0.0);
    room.furniture.push_back(make_box(at(p, x, height + 0.1 + mh, 0.15 + 0.5 * hz), p.yaw + pi + twist, {w, mh, 0.025},
                                      grey(rng, 10, 50), 0.5f));
    room.furniture.push_back(make_box(at(p, x, height + 0.06, 0.15 + 0.5 * hz), p.yaw, {0.03, 0.06, 0.03}, grey(rng, 20, 60)));
  }
  if (rng.chance(0.6)) {  // the computer under the desk
    room.furniture.push_back(make_box(at(p, hx - 0.2, 0.22, 0.2), p.yaw, {0.1, 0.22, 0.22}, grey(rng, 10, 60), 0.3f));
  }
  // the chair in front of the desk, facing it: its seat is z = -0.35 .. in the desk's frame
  Placement chair{0, 0, p.yaw + rng.uniform(-0.6, 0.6)};
  const Vec3 where = at(p, rng.uniform(-0.3, 0.3), 0, -hz - rng.uniform(0.05, 0.35));
  chair.x = where.x;
  chair.z = where.z;
  chair.yaw = wrap_angle(chair.yaw);
  chair_at(rng, room, chair, 0.23, rng.uniform(0.44, 0.5), rng.uniform(0.4, 0.55), tint(rng, 20, 90), true);
}

/// A free-standing panel (office partition, whiteboard, screen) or a wall meeting the room at an angle.
void add_panel(Rng& rng, Room& room) {
  const bool wall = rng.chance(0.35);
  const double half = wall ? rng.uniform(0.6, 1.5) : rng.uniform(0.5, 1.0);
  const double height = wall ? room.ceiling_y : rng.uniform(1.2, 1.9);
  Placement p;
  if (!place(rng, room, half, 0.05, false, p)) return;
  room.furniture.push_back(make_box(at(p, 0, height / 2, 0), p.yaw, {half, height / 2, rng.uniform(0.02, 0.06)},
                                    tint(rng, 80, 230)));
}

/// A small thing on the floor: a bin, a bag or a backpack, a pile of paper.
void add_small_thing(Rng& rng, Room& room) {
  const double r = rng.uniform(0.1, 0.2);
  Placement p;
  if (!place(rng, room, r, r, rng.chance(0.5), p)) return;
  if (rng.chance(0.5)) {
    room.furniture.push_back(make_capsule(at(p, 0, r * 0.6, 0), at(p, 0, rng.uniform(0.25, 0.45), 0), r, tint(rng, 20, 200)));
  } else {
    room.furniture.push_back(make_box(at(p, 0, r, 0), p.yaw, {r, r, r * 0.6}, tint(rng, 15, 120), 0.2f));
  }
}

/// A service robot: a wheeled base, a body, sometimes an arm, a head with a screen.
void add_service_robot(Rng& rng, Room& room) {
  const double r = rng.uniform(0.2, 0.3);
  Placement p;
  if (!place(rng, room, r, r, false, p)) return;
  const double height = rng.uniform(1.1, 1.5);
  const cv::Vec3b colour = tint(rng, 120, 240);
  room.furniture.push_back(make_capsule(at(p, 0, 0.12, 0), at(p, 0, 0.16, 0), r, grey(rng, 20, 60), 0.2f));
  room.furniture.push_back(make_box(at(p, 0, height * 0.45, 0), p.yaw, {r * 0.6, height * 0.3, r * 0.5}, colour));
  room.furniture.push_back(make_capsule(at(p, 0, height * 0.75, 0), at(p, 0, height - 0.12, 0), 0.04, colour));
  room.furniture.push_back(make_box(at(p, 0, height - 0.08, 0.03), p.yaw, {0.14, 0.1, 0.05}, grey(rng, 10, 40), 0.4f));
  if (rng.chance(0.5)) {
    const double side = rng.chance(0.5) ? 1 : -1;
    room.furniture.push_back(make_capsule(at(p, side * r * 0.6, height * 0.7, 0),
                                          at(p, side * (r * 0.6 + 0.1), height * 0.45, 0.2), 0.035, colour));
  }
}

// The kind of room: an ordinary room, a corridor, an open-plan office or hall.
struct RoomKind {
  bool corridor = false, open_plan = false;
  /// Furniture and clutter scale with the floor's area.
  double area_factor() const { return open_plan ? 1.6 : corridor ? 0.6 : 1.0; }
};

// The room's kind, walls, ceiling, colours and surfaces' dropout.
RoomKind draw_shell(Rng& rng, const RoomParams& params, Room& room) {
  const double kind = params.room_kinds ? rng.uniform() : 1.0;
  RoomKind k;
  k.corridor = kind < params.corridor_share;
  k.open_plan = !k.corridor && kind < params.corridor_share + params.open_plan_share;
  room.kind = k.corridor ? "corridor" : k.open_plan ? "open-plan" : "room";
  if (k.corridor) {
    room.front_z = rng.uniform(6.0, params.deep_front_max_m);
    room.left_x = -rng.uniform(0.8, 1.5);
    room.right_x = rng.uniform(0.8, 1.5);
  } else if (k.open_plan) {
    room.front_z = rng.uniform(5.5, params.deep_front_max_m);
    room.left_x = -rng.uniform(2.5, 5.0);
    room.right_x = rng.uniform(2.5, 5.0);
  } else {
    room.front_z = rng.chance(params.deep_room_share) ? rng.uniform(params.front_max_m, params.deep_front_max_m)
                                                      : rng.uniform(params.front_min_m, params.front_max_m);
    room.left_x = -rng.uniform(params.side_min_m, params.side_max_m);
    room.right_x = rng.uniform(params.side_min_m, params.side_max_m);
  }
  room.back_z = -rng.uniform(0.3, 1.0);
  room.ceiling_y = rng.uniform(2.4, 3.2);
  room.floor_colour = tint(rng, 50, 170);
  room.wall_colour = tint(rng, 160, 240);
  room.ceiling_colour = grey(rng, 200, 250);
  room.floor_dropout = static_cast<float>(rng.uniform(0.0, params.floor_dropout_max));
  room.wall_dropout = static_cast<float>(rng.uniform(0.0, params.wall_dropout_max));
  return k;
}

// The camera's height, pitch, roll, yaw and sideways offset in the room.
CameraPose draw_camera(Rng& rng, const RoomParams& params, const Room& room, const RoomKind& kind) {
  CameraPose camera;
  camera.height_m = rng.uniform(params.camera_height_min_m, params.camera_height_max_m);
  camera.pitch_rad = rng.uniform(params.pitch_min_deg, params.pitch_max_deg) * pi / 180.0;
  // (each drawn only when asked for, so that --classic draws the same numbers as the generator before)
  if (params.roll_max_deg > 0) camera.roll_rad = rng.uniform(-params.roll_max_deg, params.roll_max_deg) * pi / 180.0;
  if (params.yaw_max_deg > 0) {
    camera.yaw_rad = rng.uniform(-params.yaw_max_deg, params.yaw_max_deg) * pi / 180.0 * (kind.corridor ? 0.3 : 1.0);
  }
  if (params.camera_offset_max_m > 0) {
    const double x_room = std::max(0.0, std::min(-room.left_x, room.right_x) - 0.5);
    camera.x_m = rng.uniform(-1.0, 1.0) * std::min(params.camera_offset_max_m, x_room);
  }
  return camera;
}

// Up to two windows in the side and front walls.
void add_windows(Rng& rng, Room& room) {
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
}

// Tables and desks, chairs, shelves and cupboards, boxes, coat stands, robots and cabinets.
void add_furniture(Rng& rng, const RoomParams& params, const RoomKind& kind, Room& room) {
  const int pieces =
      static_cast<int>(std::lround(rng.integer(params.furniture_min, params.furniture_max) * kind.area_factor()));
  for (int k = 0; k < pieces; ++k) {
    const double pick = rng.uniform();
    if (pick < 0.18) {
      if (params.clutter && (kind.open_plan || rng.chance(0.5))) add_desk(rng, room); else add_table(rng, room);
    } else if (pick < 0.40) {
      add_chair(rng, room, params.clutter);
    } else if (pick < 0.55) {
      if (params.clutter && rng.chance(0.35)) add_cupboard(rng, room); else add_shelf(rng, room);
    } else if (pick < 0.70) {
      if (params.clutter && rng.chance(0.4)) add_small_thing(rng, room); else add_boxes(rng, room);
    } else if (pick < 0.80) {
      if (params.clutter && rng.chance(0.6)) add_coat_rack(rng, room); else add_coat_stand(rng, room);
    } else if (pick < 0.88) {
      if (params.clutter && rng.chance(0.5)) add_service_robot(rng, room); else add_robot(rng, room);
    } else {
      add_cabinet(rng, room);
    }
  }
}

// More of what labs and offices hold, person-sized and not (params.clutter).
void add_clutter(Rng& rng, const RoomParams& params, const RoomKind& kind, Room& room) {
  const int extra = static_cast<int>(std::lround(rng.integer(params.clutter_min, params.clutter_max) * kind.area_factor()));
  for (int k = 0; k < extra; ++k) {
    const double pick = rng.uniform();
    if (pick < 0.22) {
      add_plant(rng, room);
    } else if (pick < 0.34) {
      add_lamp(rng, room);
    } else if (pick < 0.46) {
      add_door(rng, room);
    } else if (pick < 0.54) {
      add_stacked_chairs(rng, room);
    } else if (pick < 0.66) {
      add_coat_rack(rng, room);
    } else if (pick < 0.76) {
      add_panel(rng, room);
    } else if (pick < 0.88) {
      add_small_thing(rng, room);
    } else {
      add_service_robot(rng, room);
    }
  }
}

// Moves what was added to `room` since (shapes, footprints, seats) by (dx, dz) on the floor plan.
void move_added(Room& room, std::size_t shapes, std::size_t footprints, std::size_t seats, double dx, double dz) {
  const Vec3 d{dx, 0, dz};
  for (std::size_t i = shapes; i < room.furniture.size(); ++i) {
    Shape& s = room.furniture[i];
    s.a = s.a + d, s.b = s.b + d, s.centre = s.centre + d;
  }
  for (std::size_t i = footprints; i < room.footprints.size(); ++i) room.footprints[i].x += dx, room.footprints[i].z += dz;
  for (std::size_t i = seats; i < room.seats.size(); ++i) room.seats[i].x += dx, room.seats[i].z += dz;
}

// RoomParams::near_clutter_max: each piece is placed as anywhere in the room, then moved so that its
// footprint's centre stands 0.6-1.6 m from the camera within 20 degrees of its heading (overlapping what
// stands there: the nearest surface is what the camera sees).
void add_near_clutter(Rng& rng, const RoomParams& params, const CameraPose& camera, Room& room) {
  const std::function<void(Rng&, Room&)> adders[] = {
      add_boxes, add_small_thing, add_plant, add_stacked_chairs, add_desk, add_cupboard, add_panel,
      add_coat_rack, add_cabinet, add_shelf, add_service_robot, add_table,
      [&params](Rng& r, Room& m) { add_chair(r, m, params.clutter); },
  };
  constexpr int kAdders = static_cast<int>(sizeof adders / sizeof adders[0]);
  const int count = rng.integer(1, params.near_clutter_max);
  for (int k = 0; k < count; ++k) {
    const std::size_t shapes = room.furniture.size(), footprints = room.footprints.size(), seats = room.seats.size();
    adders[rng.integer(0, kAdders - 1)](rng, room);
    if (room.footprints.size() == footprints) continue;  // no free spot for it anywhere
    const double distance_m = rng.uniform(0.6, 1.6), heading = camera.yaw_rad + rng.uniform(-20.0, 20.0) * pi / 180.0;
    const Footprint& f = room.footprints[footprints];
    move_added(room, shapes, footprints, seats, camera.x_m + distance_m * std::sin(heading) - f.x,
               camera.z_m + distance_m * std::cos(heading) - f.z);
  }
}

}  // namespace

Room generate_room(Rng& rng, const RoomParams& params, CameraPose& camera) {
  Room room;
  const RoomKind kind = draw_shell(rng, params, room);
  camera = draw_camera(rng, params, room, kind);
  add_windows(rng, room);
  // keep the camera's own spot (and its way forward) free of clutter
  const bool camera_spot = params.clutter || params.moving_share > 0;
  if (camera_spot) room.footprints.push_back({camera.x_m, 0.4, 0.4, 0.9, 0.0});
  add_furniture(rng, params, kind, room);
  if (params.clutter) add_clutter(rng, params, kind, room);
  if (camera_spot) room.footprints.erase(room.footprints.begin());  // the camera's spot: people may walk there
  if (params.near_clutter_max > 0) add_near_clutter(rng, params, camera, room);
  // materials: dark, glossy or finely structured surfaces lose some readings in patches
  for (Shape& shape : room.furniture) {
    shape.dropout = std::max(shape.dropout, static_cast<float>(rng.uniform(0.0, params.furniture_dropout_max)));
  }
  return room;
}

CameraPath plan_camera_path(Rng& rng, const RoomParams& params, const Room& room, const CameraPose& start) {
  CameraPath path;
  path.start = start;
  if (rng.chance(params.moving_share)) {
    path.forward_mps = rng.uniform(-0.3, 1.0) * params.camera_speed_max_mps;
    path.yaw_rate_rad_s = rng.uniform(-1.0, 1.0) * params.camera_turn_max_deg_s * pi / 180.0;
    path.wobble_rad = params.camera_wobble_deg * pi / 180.0;
    path.wobble_hz = rng.uniform(1.0, 3.0);
    path.wobble_phase = rng.uniform(0, 2 * pi);
  }
  path.min_z = room.back_z + 0.3;
  path.max_z = std::max(path.min_z, std::min(start.z_m + 0.6, room.front_z - 2.0));
  path.min_x = room.left_x + 0.4;
  path.max_x = std::max(path.min_x, room.right_x - 0.4);
  return path;
}

CameraPose CameraPath::at(double t_s) const {
  CameraPose pose = start;
  if (forward_mps == 0 && yaw_rate_rad_s == 0) return pose;
  // the heading turns at a constant rate; the position follows the heading (an arc)
  pose.yaw_rad = start.yaw_rad + yaw_rate_rad_s * t_s;
  double x = start.x_m, z = start.z_m;
  const int steps = std::max(1, static_cast<int>(t_s / 0.05));
  for (int k = 0; k < steps; ++k) {
    const double yaw = start.yaw_rad + yaw_rate_rad_s * (k + 0.5) * t_s / steps;
    x += forward_mps * t_s / steps * std::sin(yaw);
    z += forward_mps * t_s / steps * std::cos(yaw);
  }
  pose.x_m = std::clamp(x, min_x, max_x);
  pose.z_m = std::clamp(z, min_z, max_z);
  // a driving robot rocks a little
  pose.pitch_rad += wobble_rad * std::sin(2 * pi * wobble_hz * t_s + wobble_phase);
  pose.roll_rad += 0.6 * wobble_rad * std::sin(2 * pi * wobble_hz * 1.3 * t_s + 2 * wobble_phase);
  return pose;
}

}  // namespace rdsf::synth
