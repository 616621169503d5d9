#pragma once
// A synthetic Kinect recording, frame by frame: the frames are cut into clips (clip_frames each); every
// clip has its own room, camera pose and people (planned once per clip), and every frame is rendered and
// passed through the sensor model. Each frame comes with its ground truth: for every person with visible
// pixels, the tight box around those pixels, the visible fraction and the distance.
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "rdsf/frame/camera_model.hpp"
#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/synth/kinect_sensor.hpp"
#include "rdsf/synth/people_planner.hpp"
#include "rdsf/synth/renderer.hpp"
#include "rdsf/synth/room_generator.hpp"
#include "rdsf/synth/synth_params.hpp"

namespace rdsf::synth {

struct PersonTruth {
  int track = 0;  ///< id of the person, unique in the recording, stable across frames
  cv::Rect box;   ///< tight box around the person's visible pixels
  /// visible pixels / pixels the person would cover if nothing hid it and the image had no edges
  double visible_fraction = 0;
  double distance_mm = 0;  ///< camera z of the middle of the person's torso
  long long visible_px = 0;
};

struct SynthFrame {
  std::int64_t index = 0;
  std::string name;    ///< "000042": the frame-source name (files are NAME.depth.png, NAME.rgb.png)
  cv::Mat1w depth_mm;  ///< what the sensor delivers, millimetres, 0 = no reading
  cv::Mat3b bgr;       ///< registered colour (empty without rgb)
  std::vector<PersonTruth> people;  ///< ordered by track id

  /// The frame as a frame source reading its recording gives it: depth, colour, index, name, timestamp
  /// (index x kFrameIntervalUs, as for every image folder) and `camera` (SynthParams::camera()).
  DepthFrame depth_frame(const CameraModel& camera) const;
};

/// What a clip is (rdsf-synth's clips.csv): its room, the camera at the clip's first frame and whether it
/// drives, the sensor's capture profile, and the people planned for it.
struct ClipDescription {
  int clip = 0;
  int first_frame = 0;
  std::string room;            ///< Room::kind
  double room_width_m = 0;     ///< between the side walls
  double front_wall_m = 0;     ///< from the camera's starting point along the room's depth
  double camera_height_m = 0;
  double pitch_deg = 0;        ///< downward tilt
  double roll_deg = 0;
  bool moving = false;         ///< the camera drives or turns during the clip
  double noise_factor = 1;     ///< SensorProfile::noise_factor (Xtion-like clips above 1)
  double eight_bit_step_mm = 0;  ///< SensorProfile::eight_bit_step_mm (0: 16-bit millimetres)
  int people = 0;
  int furniture_shapes = 0;    ///< solids of the furniture and clutter (a table is several)
};

class SynthSequence {
 public:
  /// Throws Error when `params` are impossible (SynthParams::validate).
  explicit SynthSequence(SynthParams params);
  const SynthParams& params() const { return params_; }
  int frame_count() const { return params_.frames; }

  /// Renders frame `index` (0-based). Any order works; frames of one clip are fastest in a row.
  SynthFrame frame(int index);

  /// The scene of frame `index` and its ideal rendering (for tests and benchmarks).
  const Scene& scene_of(int index);
  const RenderBuffers& render_ideal(int index);

  /// Clip `clip` (0-based; frames clip * clip_frames onwards) as above.
  ClipDescription describe_clip(int clip);

  /// "NNNNNN" for frame `index`.
  static std::string frame_name(std::int64_t index);

 private:
  struct Clip {
    int index = -1;
    Room room;
    CameraPath camera;
    SensorProfile profile;
    std::vector<PersonTrack> tracks;
  };
  void load_clip(int clip);
  void build_scene(int index);

  SynthParams params_;
  Renderer renderer_;
  KinectSensor sensor_;
  Clip clip_;
  Scene scene_;
  int scene_index_ = -1;
  RenderBuffers buffers_;
  int buffers_index_ = -1;
  std::vector<int> shape_owner_;  ///< per scene shape: index into clip_.tracks, or -1
};

}  // namespace rdsf::synth
