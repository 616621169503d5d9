#include "rdsf/synth/synth_params.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <exception>

#include "rdsf/core/error.hpp"

namespace rdsf::synth {
namespace {

bool parse_int(const std::string& text, int& value) {
  if (text.empty() || text.size() > 7) return false;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  }
  value = std::stoi(text);
  return true;
}

bool parse_real(const std::string& text, double& value) {
  if (text.empty() || text.size() > 12) return false;
  std::size_t used = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size() && std::isfinite(value);
}

/// "AxB" -> (A, B), each read by `parse`; false for anything else.
template <typename T, typename Parse>
bool parse_pair(const std::string& text, T& a, T& b, Parse parse) {
  const std::size_t x = text.find('x');
  return x != std::string::npos && parse(text.substr(0, x), a) && parse(text.substr(x + 1), b);
}

/// "MIN..MAX" -> (MIN, MAX), "V" -> (V, V), each read by `parse`. Throws Error naming `option` and the text
/// with `expected` for anything else, and for MIN > MAX.
template <typename T, typename Parse>
void parse_range(const std::string& option, const std::string& text, T& low, T& high, Parse parse,
                 const char* expected) {
  const std::size_t dots = text.find("..");
  T a{}, b{};
  const bool ok = dots == std::string::npos
                      ? parse(text, a) && parse(text, b)
                      : parse(text.substr(0, dots), a) && parse(text.substr(dots + 2), b);
  if (!ok) fail(option + " " + text, expected);
  if (a > b) fail(option + " " + text, "MIN is larger than MAX");
  low = a;
  high = b;
}

std::string number(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

void need_value(const std::string& option, double value, double min, double max, const char* unit) {
  if (!(value >= min && value <= max)) fail(option + " " + number(value), "must lie in " + number(min) + ".." + number(max) + " " + unit);
}

void need_share(const std::string& option, double value) {
  if (!(value >= 0.0 && value <= 1.0)) fail(option + " " + number(value), "must be a share in 0..1");
}

void need_range(const std::string& option, double low, double high, double min, double max, const char* unit) {
  if (!(low >= min && high <= max && low <= high)) {
    char text[200];
    std::snprintf(text, sizeof text, "%s %g..%g", option.c_str(), low, high);
    char what[200];
    std::snprintf(what, sizeof what, "must lie in %g..%g %s with MIN <= MAX", min, max, unit);
    fail(text, what);
  }
}

}  // namespace

SynthParams people_scene(int frames, int people_min, int people_max, std::uint64_t seed) {
  SynthParams p;
  p.frames = frames;
  p.people_min = people_min;
  p.people_max = people_max;
  p.seed = seed;
  return p;
}

void parse_real_range(const std::string& option, const std::string& text, double& low, double& high) {
  parse_range(option, text, low, high, parse_real, "expected MIN..MAX (two numbers, e.g. 0.5..1.6) or one number");
}

bool parse_on_off(const std::string& option, const std::string& text) {
  if (text == "on") return true;
  if (text == "off") return false;
  fail(option + " " + text, "expected on or off");
}

void SynthParams::set_classic() {
  room.camera_height_min_m = 0.7;
  room.camera_height_max_m = 1.2;
  room.roll_max_deg = 0;
  room.yaw_max_deg = 0;
  room.camera_offset_max_m = 0;
  room.moving_share = 0;
  room.clutter = false;
  room.room_kinds = false;
  room.floor_dropout_max = 0.2;
  room.wall_dropout_max = 0.05;
  sensor.eight_bit_share = 0;
  sensor.xtion_share = 0;
  sensor.patch_cell_px = 20;
  sensor.coherent_holes_px = 0;
  people.body.varied_bodies = false;
  people.body.outfits = false;
  people.poses = false;
  people.group_share = 0;
  people.sitting_share = 0;
  people.in_view_share = 0;
  people.nearest_m = 1.0;
  people.farthest_m = 7.0;
  people.clearance_m = 0.5;
}

void parse_people_range(const std::string& text, int& people_min, int& people_max) {
  parse_range("--people", text, people_min, people_max, parse_int,
              "expected MIN..MAX (two whole numbers, e.g. 0..3) or one number");
}

void parse_field_of_view(const std::string& text, double& fov_h_deg, double& fov_v_deg) {
  if (text == "kinect") {
    fov_h_deg = fov_v_deg = 0;
    return;
  }
  if (!parse_pair(text, fov_h_deg, fov_v_deg, parse_real)) {
    fail("--fov " + text, "expected HORIZONTALxVERTICAL in degrees, e.g. 87x58, or kinect");
  }
}

CameraModel SynthParams::camera() const {
  if (fov_h_deg <= 0 && fov_v_deg <= 0) return CameraModel::kinect_v1().scaled_to(width_px, height_px);
  return CameraModel::from_field_of_view(width_px, height_px, fov_h_deg, fov_v_deg);
}

void parse_image_size(const std::string& text, int& width_px, int& height_px) {
  int w = 0, h = 0;
  if (!parse_pair(text, w, h, parse_int)) {
    fail("--size " + text, "expected WIDTHxHEIGHT in pixels, e.g. 640x480");
  }
  width_px = w;
  height_px = h;
}

void SynthParams::validate() const {
  if (frames < 1 || frames > 999999) fail("--frames " + std::to_string(frames), "must be 1..999999");
  const std::string people_text =
      "--people " + std::to_string(people_min) + ".." + std::to_string(people_max);
  if (people_min < 0) fail(people_text, "MIN must not be negative");
  if (people_min > people_max) fail(people_text, "MIN is larger than MAX");
  if (people_max > 20) fail(people_text, "at most 20 people fit in a room");
  const std::string size = "--size " + std::to_string(width_px) + "x" + std::to_string(height_px);
  if (width_px % 8 != 0 || height_px % 8 != 0) fail(size, "width and height must be multiples of 8");
  if (width_px < 64 || height_px < 48 || width_px > 1920 || height_px > 1440) {
    fail(size, "must be between 64x48 and 1920x1440");
  }
  if (fov_h_deg != 0 || fov_v_deg != 0) {
    if (!(fov_h_deg >= 20 && fov_h_deg <= 150 && fov_v_deg >= 20 && fov_v_deg <= 150)) {
      fail("--fov " + number(fov_h_deg) + "x" + number(fov_v_deg), "each angle must lie in 20..150 degrees");
    }
  }
  if (clip_frames < 1) fail("--clip-frames " + std::to_string(clip_frames), "must be at least 1");
  need_range("--camera-height", room.camera_height_min_m, room.camera_height_max_m, 0.2, 2.5, "m");
  need_range("--camera-pitch", room.pitch_min_deg, room.pitch_max_deg, -30, 30, "degrees");
  need_value("--camera-roll", room.roll_max_deg, 0, 20, "degrees");
  need_value("--camera-yaw", room.yaw_max_deg, 0, 60, "degrees");
  need_share("--moving-camera", room.moving_share);
  need_value("--camera-speed", room.camera_speed_max_mps, 0, 1.5, "m/s");
  need_range("--clutter", room.clutter_min, room.clutter_max, 0, 40, "pieces");
  need_range("--furniture", room.furniture_min, room.furniture_max, 0, 40, "pieces");
  need_share("--corridors", room.corridor_share);
  need_share("--open-plan", room.open_plan_share);
  if (room.corridor_share + room.open_plan_share > 1.0) {
    fail("--corridors " + number(room.corridor_share) + " --open-plan " + number(room.open_plan_share),
         "the two shares add up to more than 1");
  }
  need_share("--eight-bit", sensor.eight_bit_share);
  need_range("--eight-bit-step", sensor.eight_bit_step_min_mm, sensor.eight_bit_step_max_mm, 1, 60, "mm");
  need_share("--xtion", sensor.xtion_share);
  if (sensor.coherent_holes_px < 0 || sensor.coherent_holes_px > 8) {
    fail("--coherent-holes " + std::to_string(sensor.coherent_holes_px), "must be 0..8 pixels");
  }
  need_share("--children", people.body.child_share);
  need_share("--sitting", people.sitting_share);
  need_share("--groups", people.group_share);
  need_range("--people-distance", people.nearest_m, people.farthest_m, 0.5, 10, "m");
  need_value("--wall-clearance", people.clearance_m, 0.2, 1, "m");
}

}  // namespace rdsf::synth
