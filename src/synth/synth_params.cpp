#include "synth/synth_params.hpp"

#include <cctype>

#include "core/error.hpp"

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

}  // namespace

void parse_people_range(const std::string& text, int& people_min, int& people_max) {
  const std::size_t dots = text.find("..");
  int low = 0, high = 0;
  const bool ok = dots == std::string::npos
                      ? parse_int(text, low) && parse_int(text, high)
                      : parse_int(text.substr(0, dots), low) && parse_int(text.substr(dots + 2), high);
  if (!ok) fail("--people " + text, "expected MIN..MAX (two whole numbers, e.g. 0..3) or one number");
  if (low > high) fail("--people " + text, "MIN is larger than MAX");
  people_min = low;
  people_max = high;
}

void parse_image_size(const std::string& text, int& width_px, int& height_px) {
  const std::size_t x = text.find('x');
  int w = 0, h = 0;
  if (x == std::string::npos || !parse_int(text.substr(0, x), w) || !parse_int(text.substr(x + 1), h)) {
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
  if (clip_frames < 1) fail("--clip-frames " + std::to_string(clip_frames), "must be at least 1");
}

}  // namespace rdsf::synth
