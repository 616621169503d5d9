#pragma once
// rdsf-background's work: learn a background model of the room from a static camera's frames
// (rdsf/segmentation/background_model.hpp) and write it for rdsf-detect --background.
#include <cstdint>
#include <string>

#include "rdsf/frame/camera_model.hpp"
#include "rdsf/frame/frame_source.hpp"

namespace rdsf {

struct BackgroundOptions {
  std::string source;
  std::string out;            ///< the folder written: background.depth.png and camera.yml
  std::int64_t frames = 200;  ///< learn from at most this many frames, spread evenly over the source
  double quantile = 0.8;      ///< per pixel, this quantile of its readings (frames without one left out)
  bool force = false;         ///< replace an existing background in --out
  CameraModel camera;
  FrameSourceOptions frame_options;
};

/// Returns the process exit code.
int run_background(const BackgroundOptions& options);

}  // namespace rdsf
