#pragma once
// camera.yml: the camera model of a folder of PNG frames, beside the frames (versioned, written by the
// workbench's scripts or by hand):
//
//   %YAML:1.0
//   ---
//   format: rdsf-camera
//   format_version: 1
//   width_px: 512          # every frame of the folder has this size (another size is an Error)
//   height_px: 424
//   fx_px: 365.0           # pinhole intrinsics of the depth image, pixels (CameraModel)
//   fy_px: 365.0
//   cx_px: 255.5
//   cy_px: 211.5
//   depth_unit_mm: 1       # optional: millimetres per PNG value (1 by default; 0.25 for quarter-mm units)
//
// Read through core/yaml_guard and cv::FileStorage like the other YAML files; a bad file is an Error with
// one line naming it and the problem.
#include <string>

#include "rdsf/frame/camera_model.hpp"

namespace rdsf {

struct CameraFile {
  static constexpr const char* kFileName = "camera.yml";
  static constexpr const char* kFormat = "rdsf-camera";
  static constexpr int kFormatVersion = 1;

  CameraModel camera;
  double depth_unit_mm = 1.0;  ///< millimetres per stored depth value: depth_mm = round(value * depth_unit_mm)
};

/// Parses the text of a camera.yml; `path` names it in errors. Sizes 1..16384 px, focal lengths > 0,
/// the principal point inside the image, 0 < depth_unit_mm <= 100.
CameraFile parse_camera_file(const std::string& text, const std::string& path);
/// Reads and parses the file at `path`.
CameraFile read_camera_file(const std::string& path);
/// The text of a camera.yml (parse_camera_file reads it back to the same values).
std::string camera_file_text(const CameraFile& file);

}  // namespace rdsf
