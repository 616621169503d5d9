#pragma once
// The address of a virtual sensor: "rdsf-png://<folder>[?option&option...]", e.g. "rdsf-png:///data/take1"
// or "rdsf-png://frames?fps=15" (a relative folder is taken from the working folder of the program).
// Options:
//   fps=N       frames per second, 1..1000 (default 30, as a Kinect);
//   depth=off   offer no depth stream (a colour-only camera; needs NAME.rgb.png);
//   crop=off    do not offer the cropping property, as OpenNI2's Dummy device: recordings then lack it and
//               OpenNI2's file player delivers none of their frames (kept to test that diagnosis);
//   hfov=DEG    the horizontal field of view both streams report, in degrees, (0, 180) exclusive (default:
//               a Kinect v1's registered stream, a focal length of 525 px at 640 px wide, 62.7 degrees);
//               the vertical one follows from square pixels: vfov = 2 atan(height / 2 / f), f = width / 2 /
//               tan(hfov / 2).
#include <string>

namespace rdsf::openni_driver {

inline constexpr const char* kUriScheme = "rdsf-png://";

struct PngDeviceUri {
  std::string folder;
  int fps = 30;
  bool depth = true;
  bool cropping = true;
  double hfov_deg = 0.0;  ///< 0: a focal length of 525 px at 640 px wide, scaled with the width
};

/// True when `uri` starts with the virtual sensor's scheme.
bool is_png_device_uri(const std::string& uri);

/// Splits `uri`. Returns false and sets `error` (one line) when the scheme is wrong, the folder is empty
/// or an option is unknown or out of range.
bool parse_png_device_uri(const std::string& uri, PngDeviceUri& parsed, std::string& error);

}  // namespace rdsf::openni_driver
