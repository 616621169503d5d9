#pragma once
// rdsf-detect's work: run the detector core over a frame source, write the CSV, save or show pictures.
#include <string>

#include "detector/detector_core.hpp"
#include "frame/camera_model.hpp"

namespace rdsf {

struct DetectOptions {
  std::string source;
  std::string out_csv;   ///< empty: no CSV
  std::string save_dir;  ///< empty: no pictures
  bool show = false;
  bool force = false;    ///< replace an existing CSV
  CameraModel camera;
  DetectorParams detector;
};

/// Returns the process exit code.
int run_detect(const DetectOptions& options);

}  // namespace rdsf
