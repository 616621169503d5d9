#pragma once
// rdsf-pcl-people's work: PCL's ground-based people detector (pcl::people::GroundBasedPeopleDetectionApp,
// HOG+SVM on the colour image) over a frame source with colour, the floor fitted per recording
// (ground_plane.hpp), written as rdsf-detect's detection CSV and evaluated with the workbench's own
// matching and figures (rdsf/evaluation/threshold_sweep.hpp) against a boxes.csv.
//
// Each PCL person cluster is one row: its box is the bounding box of the cluster's points projected with
// the camera model (a tight box like the truth's), depth_mm the cluster's distance, score PCL's HOG+SVM
// confidence (the app's default threshold is -1.5). PCL does not track: `person` is the cluster's number
// in its frame (1, 2, ...) when its confidence >= min_confidence, else empty; distance_cm is 0. A cluster
// whose HOG window PCL cannot evaluate (NaN: the window leaves the image; never a person in PCL's app) has
// score -10.
// For the evaluation's probability thresholds a confidence c reads as P = 1 / (1 + exp(-2 c)) (the
// calibration "none"); the exact curve and TAR at FPPF <= x do not depend on it.
// A recording is the frames whose names agree up to their first digit ("lab_alberto1" and "lab_alberto2"
// are "lab_alberto", every "home_2013-..." frame is "home_"): one static camera each.
#include <string>

#include "ground_plane.hpp"
#include "rdsf/frame/camera_model.hpp"

namespace rdsf::peers {

struct PclPeopleOptions {
  std::string source;       ///< frames with colour (NAME.depth.png + NAME.rgb.png)
  std::string svm;          ///< PCL's HOG+SVM file
  std::string out_csv;      ///< detection CSV (rdsf-detect's format with a model)
  std::string truth_csv;    ///< boxes.csv: evaluate (needs report_dir)
  std::string report_dir;
  bool force = false;
  double min_confidence = -1.5;  ///< PCL app's default: a cluster is a person above it
  double min_height_m = 1.3, max_height_m = 2.3;  ///< PCL app's defaults
  double min_width_m = 0.1, max_width_m = 8.0;
  double voxel_size_m = 0.06;
  double min_visible = 0.5;
  int clip_frames = 100;  ///< numbered frames per clip of the intervals over clips (clip_bootstrap.hpp)
  CameraModel camera;
  GroundParams ground;
};

/// Returns the process exit code.
int run_pcl_people(const PclPeopleOptions& o);

}  // namespace rdsf::peers
