#pragma once
// Where frames come from. Every source delivers each frame exactly once, in order, and throws
// rdsf::Error (one line naming the file or device) on bad input: no frame is ever skipped silently.
//
// open_frame_source() chooses the source from one --source argument:
//   - "openni" (the first attached device) or a device URI (contains "://"): a live OpenNI2 device;
//   - a path ending in ".oni": an OpenNI2 recording, read frame by frame;
//     (a build without OpenNI2, RDSF_WITH_OPENNI 0 in rdsf/version.hpp, refuses both with one line);
//   - a folder: every NAME.depth.png in it (sorted by name), with NAME.rgb.png as colour when present;
//   - a path ending in ".bag": a ROS 1 bag (rdsf/frame/bag_source.hpp; a build without librosbag,
//     RDSF_WITH_ROSBAG 0 in rdsf/version.hpp, refuses it with one line);
//   - a single NAME.depth.png file: that one frame;
//   - any other file: a list file, one depth PNG path a line (relative to the list's folder; # comments).
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rdsf/frame/camera_model.hpp"
#include "rdsf/frame/depth_frame.hpp"

namespace rdsf {

/// The rest of reading a frame (decoding its images), which may run on another thread: see next_deferred().
using FrameDecode = std::function<DepthFrame()>;

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  /// Fills `frame` with the next frame and returns true; returns false at the end of the source.
  virtual bool next(DepthFrame& frame) = 0;
  /// Reads the next frame as far as it must be read in order (a bag's next messages and their pairing) and
  /// returns true with the rest in `decode`, or false at the end. decode() gives the frame next() would have
  /// given; it may be called later on another thread, concurrently with further reads and other decodes (the
  /// source must outlive it). Default: next() at once. PNG folders and bags defer their images' decoding, so
  /// run_in_frame_order decodes them on its workers.
  virtual bool next_deferred(FrameDecode& decode);
  /// What this source reads, for messages ("folder ../shared/realdata/people (32 frames)").
  virtual std::string description() const = 0;
  /// Number of frames when known in advance (files), nothing for live devices.
  virtual std::optional<std::int64_t> frame_count() const = 0;
  /// The names next() gives the frames, in order, when known before reading them (files): a PNG source's file
  /// stems, a recording's indices "0", "1", ... (index_frame_names); nothing for live devices and, by default,
  /// for a source a program derives itself.
  virtual std::optional<std::vector<std::string>> frame_names() const { return std::nullopt; }
  /// What the source has to say after reading (a bag: the colour pairing gaps), empty when nothing.
  virtual std::string summary() const { return {}; }
};

/// How a source is opened beyond its path: the camera model to fall back on and what a bag is read for.
struct FrameSourceOptions {
  /// The model frames carry when the source has none of its own (camera.yml, CameraInfo, OpenNI2's field
  /// of view); rescaled to the frame size when the frames are of another size.
  CameraModel camera = CameraModel::kinect_v1();
  /// True when `camera` was given by the user: it then wins over the source's own model.
  bool camera_given = false;
  std::string depth_topic;   ///< bags: the depth image topic; empty = the bag's one depth image topic
  std::string colour_topic;  ///< bags: the colour topic; empty = the one of the depth's size, "none" = no colour
  /// bags: the largest stamp gap (ms) of a depth frame and the colour frame paired with it (100: three frames at
  /// 30 fps; a robot's snapshot recorder may keep colour a few hundred ms after its depth).
  double colour_gap_ms = 100;
};

/// Opens the source named by `spec`. `camera` is the model frames carry unless the source knows better;
/// it is rescaled to the frame size when the frames are not 640x480.
std::unique_ptr<FrameSource> open_frame_source(const std::string& spec,
                                               const CameraModel& camera = CameraModel::kinect_v1());

/// The same with every option (camera model, bag topics).
std::unique_ptr<FrameSource> open_frame_source(const std::string& spec, const FrameSourceOptions& options);

/// "0", "1", ..., "count - 1": the names of a recording's frames (bags, .oni files).
std::vector<std::string> index_frame_names(std::int64_t count);

/// True when `spec` names a ROS 1 bag (ends in ".bag").
bool is_bag_spec(const std::string& spec);

/// True when `spec` names an OpenNI2 recording or device rather than image files.
bool is_openni_spec(const std::string& spec);

}  // namespace rdsf
