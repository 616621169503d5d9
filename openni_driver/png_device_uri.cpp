#include "png_device_uri.hpp"

#include <cstdlib>
#include <cstring>

namespace rdsf::openni_driver {
namespace {

bool parse_fps(const std::string& text, int& fps) {
  if (text.empty() || text.size() > 4) return false;
  for (char c : text) {
    if (c < '0' || c > '9') return false;
  }
  fps = std::stoi(text);
  return fps >= 1 && fps <= 1000;
}

bool parse_degrees(const std::string& text, double& degrees) {
  if (text.empty() || text.size() > 12) return false;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !(value > 0.0 && value < 180.0)) return false;
  degrees = value;
  return true;
}

bool apply_option(const std::string& option, PngDeviceUri& parsed) {
  if (option.rfind("fps=", 0) == 0) return parse_fps(option.substr(4), parsed.fps);
  if (option.rfind("hfov=", 0) == 0) return parse_degrees(option.substr(5), parsed.hfov_deg);
  if (option == "depth=off") {
    parsed.depth = false;
    return true;
  }
  if (option == "crop=off") {
    parsed.cropping = false;
    return true;
  }
  return false;
}

}  // namespace

bool is_png_device_uri(const std::string& uri) { return uri.rfind(kUriScheme, 0) == 0; }

bool parse_png_device_uri(const std::string& uri, PngDeviceUri& parsed, std::string& error) {
  if (!is_png_device_uri(uri)) {
    error = uri + ": not a virtual sensor address (expected " + kUriScheme + "<folder>)";
    return false;
  }
  std::string rest = uri.substr(std::strlen(kUriScheme));
  parsed = PngDeviceUri{};
  const std::size_t query = rest.find('?');
  if (query != std::string::npos) {
    std::string options = rest.substr(query + 1);
    rest.resize(query);
    while (true) {
      const std::size_t amp = options.find('&');
      const std::string option = options.substr(0, amp);
      if (!apply_option(option, parsed)) {
        error = uri + ": unknown option '" + option + "' (understood: fps=N with N 1..1000, depth=off, crop=off, hfov=DEG with DEG in (0, 180))";
        return false;
      }
      if (amp == std::string::npos) break;
      options.erase(0, amp + 1);
    }
  }
  if (rest.empty()) {
    error = uri + ": no folder after " + kUriScheme;
    return false;
  }
  parsed.folder = rest;
  return true;
}

}  // namespace rdsf::openni_driver
