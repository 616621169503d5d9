#include "rdsf/synth/synth_sequence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "rdsf/synth/angle.hpp"
#include "rdsf/synth/random.hpp"

namespace rdsf::synth {

namespace {
SynthParams validated(SynthParams params) {
  params.validate();
  return params;
}
}  // namespace

SynthSequence::SynthSequence(SynthParams params)
    : params_(validated(std::move(params))),
      renderer_(params_.camera()),
      sensor_(params_.camera(), params_.sensor) {}

std::string SynthSequence::frame_name(std::int64_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "%06lld", static_cast<long long>(index));
  return name;
}

void SynthSequence::load_clip(int clip) {
  if (clip_.index == clip) return;
  clip_ = Clip{};
  clip_.index = clip;
  Rng room_rng(derive_seed(params_.seed, stream_room, static_cast<std::uint64_t>(clip)));
  CameraPose start;
  clip_.room = generate_room(room_rng, params_.room, start);
  clip_.camera = plan_camera_path(room_rng, params_.room, clip_.room, start);
  Rng profile_rng(derive_seed(params_.seed, stream_profile, static_cast<std::uint64_t>(clip)));
  clip_.profile = sensor_.draw_profile(profile_rng);
  if (!params_.empty) {
    Rng people_rng(derive_seed(params_.seed, stream_people, static_cast<std::uint64_t>(clip)));
    const int count = people_rng.integer(params_.people_min, params_.people_max);
    const int first_track = clip * std::max(1, params_.people_max) + 1;
    clip_.tracks =
        plan_people(people_rng, clip_.room, count, params_.clip_frames, first_track, params_.people,
                    clip_.camera.start);
  }
}

ClipDescription SynthSequence::describe_clip(int clip) {
  load_clip(clip);
  const CameraPose& start = clip_.camera.start;
  ClipDescription d;
  d.clip = clip;
  d.first_frame = clip * params_.clip_frames;
  d.room = clip_.room.kind;
  d.room_width_m = clip_.room.right_x - clip_.room.left_x;
  d.front_wall_m = clip_.room.front_z - start.z_m;
  d.camera_height_m = start.height_m;
  d.pitch_deg = start.pitch_rad * 180.0 / pi;
  d.roll_deg = start.roll_rad * 180.0 / pi;
  d.moving = clip_.camera.forward_mps != 0.0 || clip_.camera.yaw_rate_rad_s != 0.0;
  d.noise_factor = clip_.profile.noise_factor;
  d.eight_bit_step_mm = clip_.profile.eight_bit_step_mm;
  d.people = static_cast<int>(clip_.tracks.size());
  d.furniture_shapes = static_cast<int>(clip_.room.furniture.size());
  return d;
}

void SynthSequence::build_scene(int index) {
  if (scene_index_ == index) return;
  const int clip = index / params_.clip_frames;
  const int within = index % params_.clip_frames;
  load_clip(clip);
  scene_.room = clip_.room;
  scene_.camera = clip_.camera.at(within * params_.people.frame_interval_s);
  scene_.shapes = clip_.room.furniture;
  shape_owner_.assign(scene_.shapes.size(), -1);
  for (std::size_t t = 0; t < clip_.tracks.size(); ++t) {
    const PersonTrack& track = clip_.tracks[t];
    const PersonPose& pose = track.poses[static_cast<std::size_t>(within)];
    if (!pose.present) continue;
    add_person_shapes(track.body, pose, track.track, scene_.shapes);
    shape_owner_.resize(scene_.shapes.size(), static_cast<int>(t));
  }
  scene_index_ = index;
}

const Scene& SynthSequence::scene_of(int index) {
  build_scene(index);
  return scene_;
}

const RenderBuffers& SynthSequence::render_ideal(int index) {
  build_scene(index);
  if (buffers_index_ != index) {
    renderer_.render(scene_, buffers_);
    buffers_index_ = index;
  }
  return buffers_;
}

DepthFrame SynthFrame::depth_frame(const CameraModel& camera) const {
  DepthFrame frame;
  frame.depth_mm = depth_mm;
  frame.bgr = bgr;
  frame.index = index;
  frame.name = name;
  frame.timestamp_us = index * kFrameIntervalUs;
  frame.camera = camera;
  return frame;
}

SynthFrame SynthSequence::frame(int index) {
  const RenderBuffers& buffers = render_ideal(index);
  SynthFrame frame;
  frame.index = index;
  frame.name = frame_name(index);
  frame.depth_mm = sensor_.measure(
      scene_, buffers, derive_seed(params_.seed, stream_sensor, static_cast<std::uint64_t>(index)), clip_.profile);
  if (params_.rgb) {
    Rng colour_rng(derive_seed(params_.seed, stream_colour, static_cast<std::uint64_t>(index)));
    frame.bgr = renderer_.shade(scene_, buffers, colour_rng);
  }
  if (clip_.tracks.empty()) return frame;

  // ground truth: visible pixels of each person (in the image, outside the registration band, in range)
  const std::size_t people = clip_.tracks.size();
  std::vector<long long> count(people, 0);
  std::vector<int> x0(people, 1 << 30), y0(people, 1 << 30), x1(people, -1), y1(people, -1);
  const KinectSensorParams& sp = params_.sensor;
  // what the capture can hold: the sensor's range, narrowed by an 8-bit capture's 255 steps
  double near_m = sp.min_range_m, far_m = sp.max_range_m;
  if (clip_.profile.eight_bit_step_mm > 0) {
    near_m = std::max(near_m, (clip_.profile.eight_bit_offset_mm + 0.5 * clip_.profile.eight_bit_step_mm) / 1000.0);
    far_m = std::min(far_m, (clip_.profile.eight_bit_offset_mm + 255.5 * clip_.profile.eight_bit_step_mm) / 1000.0);
  }
  for (int v = 0; v < buffers.surface.rows; ++v) {
    const std::uint16_t* surface = buffers.surface.ptr<std::uint16_t>(v);
    const float* depth = buffers.depth_m.ptr<float>(v);
    for (int u = 0; u < buffers.surface.cols; ++u) {
      if (surface[u] < first_shape_surface) continue;
      const int owner = shape_owner_[static_cast<std::size_t>(surface[u] - first_shape_surface)];
      if (owner < 0 || depth[u] < near_m || depth[u] > far_m || sensor_.in_band(u, v))
        continue;
      const std::size_t p = static_cast<std::size_t>(owner);
      ++count[p];
      x0[p] = std::min(x0[p], u);
      x1[p] = std::max(x1[p], u);
      y0[p] = std::min(y0[p], v);
      y1[p] = std::max(y1[p], v);
    }
  }
  const int within = index % params_.clip_frames;
  const CameraAxes axes(scene_.camera);
  for (std::size_t p = 0; p < people; ++p) {
    if (count[p] == 0) continue;
    std::vector<int> shapes;
    for (std::size_t i = 0; i < shape_owner_.size(); ++i) {
      if (shape_owner_[i] == static_cast<int>(p)) shapes.push_back(static_cast<int>(i));
    }
    const long long area =
        renderer_.silhouette_area(buffers, shapes, buffers.surface.cols / 2, /*step_px=*/2);
    PersonTruth truth;
    truth.track = clip_.tracks[p].track;
    truth.box = cv::Rect(x0[p], y0[p], x1[p] - x0[p] + 1, y1[p] - y0[p] + 1);
    truth.visible_px = count[p];
    truth.visible_fraction =
        area > 0 ? std::min(1.0, static_cast<double>(count[p]) / static_cast<double>(area)) : 0.0;
    const PersonPose& pose = clip_.tracks[p].poses[static_cast<std::size_t>(within)];
    const Vec3 torso = pose.position + Vec3{0, torso_height_m(clip_.tracks[p].body, pose), 0};
    truth.distance_mm = 1000.0 * axes.to_camera(torso).z;
    frame.people.push_back(truth);
  }
  return frame;
}

}  // namespace rdsf::synth
