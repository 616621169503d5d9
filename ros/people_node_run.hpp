#pragma once
// rdsf_people's work: subscribe, run rdsf::PeopleDetector in live mode (LivePipeline: newest frame wins),
// publish people, markers and diagnostics until ROS shuts down (docs/ros.md).
#include <string>

#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"

namespace rdsf {

/// --colour-gap-ms's default without waiting (--colour-wait false, the default): a frame then takes the
/// previous frame's colour image, one frame period older (33 ms at 30 frames/s, 100 at 10).
constexpr double kColourGapWithoutWaitMs = 100;
/// --colour-gap-ms's default with --colour-wait true: a frame waits for the colour image of its own stamp.
constexpr double kColourGapWaitingMs = 15;

/// How a depth image finds its camera model on depth/camera_info.
enum class CameraInfoPairing {
  exact,  ///< the camera_info of the image's own stamp (image_transport's CameraSubscriber): a live driver's
  latest  ///< the newest camera_info received, of the image's optical frame (a bag or robot whose camera_info
          ///< is stamped apart from the depth, e.g. a registered depth image with the colour camera's info)
};

struct PeopleNodeOptions {
  std::string model = kDefaultModelName;  ///< a file, NAME or NAME/vN (rdsf-detect's --model)
  std::string models_dir = "models";
  PipelineParams pipeline;  ///< its analyser's background: ~background (cli::apply_background), or none
  bool feature_spec_given = false;  ///< else the model's feature spec
  int threads = 0;                  ///< live workers (0: one per core)
  bool colour = false;              ///< subscribe to rgb/image and pair it with the depth images
  double colour_gap_ms = kColourGapWithoutWaitMs;  ///< largest depth-colour stamp difference of a pair
                                                  ///< (kColourGapWaitingMs when waiting and not given)
  /// A depth frame waits for its own colour image (ColourWait::until_paired). false, the default: it takes
  /// the colour image already there (ColourWait::never). Measured (docs/ros.md, "Latency"): the node's p99
  /// from the depth message 10.9-16 ms waiting, 4.7 ms not; tracking the same on three 960-frame synthetic
  /// sequences with colour one frame old (identity switches over all thresholds 280 / 160 / 398 waiting,
  /// 229 / 161 / 400 not); candidates, scores and people never depend on colour.
  bool colour_wait = false;
  CameraInfoPairing camera_info = CameraInfoPairing::exact;
  /// How depth and colour arrive: raw sensor_msgs/Image, or sensor_msgs/CompressedImage on the image topic's
  /// "compressedDepth" and "compressed" subtopics (image_transport's names; decoded by the node itself,
  /// frame/compressed_image.hpp, as Debian ships no image_transport plugins).
  bool compressed_depth = false;
  bool compressed_colour = false;
  double diagnostics_period_s = 1;  ///< /diagnostics every this many seconds
};

/// Runs the node until ROS shuts down (Ctrl-C, rosnode kill); returns the exit code. Call after ros::init.
int run_people_node(const PeopleNodeOptions& options);

}  // namespace rdsf
