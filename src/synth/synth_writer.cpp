#include "rdsf/synth/synth_writer.hpp"

#include <cstdio>
#include <filesystem>
#include <regex>
#include <sstream>
#include <vector>

#include "rdsf/core/durable_io.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/frame/camera_file.hpp"
#include "rdsf/frame/depth_png.hpp"

namespace rdsf::synth {
namespace fs = std::filesystem;

namespace {

bool ends_with(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

void prepare_output_folder(const std::string& dir, bool force) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) fail(dir, "exists and is not a folder");
  if (!fs::exists(dir, ec)) {
    create_folders_durably(dir);
    return;
  }
  const std::regex ours(R"(\d{6}\.(depth|rgb)\.png)");
  std::vector<fs::path> our_files;
  int foreign_frames = 0;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, ours) || name == "boxes.csv" || name == "clips.csv" || name == "synth.yml" ||
        name == CameraFile::kFileName) {
      our_files.push_back(entry.path());
    } else if (ends_with(name, ".depth.png") || ends_with(name, ".rgb.png")) {
      ++foreign_frames;
    }
  }
  if (ec) fail(dir, "cannot list folder: " + ec.message());
  if (!force && (!our_files.empty() || foreign_frames > 0)) {
    throw AlreadyExists(dir + ": already holds frames or boxes.csv (" +
                        std::to_string(our_files.size() + foreign_frames) + " files); choose another folder");
  }
  if (foreign_frames > 0) {
    fail(dir,
         "holds " + std::to_string(foreign_frames) +
             " depth/colour images not named like rdsf-synth output; only NNNNNN.depth.png, NNNNNN.rgb.png, "
             "boxes.csv, clips.csv, synth.yml and camera.yml are ever replaced: empty the folder yourself");
  }
  for (const fs::path& path : our_files) {
    fs::remove(path, ec);
    if (ec) fail(path.string(), "cannot remove: " + ec.message());
  }
}

SynthWriter::SynthWriter(std::string dir, const SynthParams& params, bool force)
    : dir_(std::move(dir)), params_(params), force_(force) {
  boxes_ = std::make_unique<AtomicTextFile>((fs::path(dir_) / "boxes.csv").string(), force_);
  boxes_->stream() << "frame,person,x,y,w,h,visible_fraction,track\n";
  clips_ = std::make_unique<AtomicTextFile>((fs::path(dir_) / "clips.csv").string(), force_);
  clips_->stream() << "clip,first_frame,room,room_width_m,front_wall_m,camera_height_m,pitch_deg,roll_deg,moving,"
                      "noise_factor,eight_bit_step_mm,people,furniture_shapes\n";
}

void SynthWriter::add_clip(const ClipDescription& c) {
  char row[256];
  std::snprintf(row, sizeof row, "%d,%06d,%s,%.2f,%.2f,%.2f,%.1f,%.1f,%d,%.2f,%.1f,%d,%d\n", c.clip, c.first_frame,
                c.room.c_str(), c.room_width_m, c.front_wall_m, c.camera_height_m, c.pitch_deg, c.roll_deg,
                c.moving ? 1 : 0, c.noise_factor, c.eight_bit_step_mm, c.people, c.furniture_shapes);
  clips_->stream() << row;
}

void SynthWriter::write(const SynthFrame& frame) {
  const fs::path base = fs::path(dir_) / frame.name;
  write_png_atomically(base.string() + ".depth.png", frame.depth_mm);
  if (!frame.bgr.empty()) write_png_atomically(base.string() + ".rgb.png", frame.bgr);
  std::ostream& out = boxes_->stream();
  for (const PersonTruth& p : frame.people) {
    char fraction[32];
    std::snprintf(fraction, sizeof fraction, "%.3f", p.visible_fraction);
    out << frame.name << ',' << p.track << ',' << p.box.x << ',' << p.box.y << ',' << p.box.width << ','
        << p.box.height << ',' << fraction << ',' << p.track << '\n';
  }
  boxes_->flush();
}

std::string SynthWriter::describe(const SynthParams& p, const std::string& command_line) {
  std::ostringstream out;
  const KinectSensorParams& s = p.sensor;
  const RoomParams& r = p.room;
  const BodyParams& b = p.people.body;
  const auto on = [](bool value) { return value ? "true" : "false"; };
  std::string command = command_line;
  for (char& c : command) {
    if (c == '"' || c == '\\' || c == '\n') c = '\'';
  }
  out << "# Synthetic Kinect v1 recording made by rdsf-synth (same options and seed give the same bytes)\n"
      << "generator: rdsf-synth 2\n"
      << "command: \"" << command << "\"\n"
      << "seed: " << p.seed << "\n"
      << "frames: " << p.frames << "\n"
      << "people: " << p.people_min << ".." << p.people_max << "\n"
      << "empty: " << (p.empty ? "true" : "false") << "\n"
      << "size: " << p.width_px << "x" << p.height_px << "\n"
      << "rgb: " << (p.rgb ? "true" : "false") << "\n"
      << "clip_frames: " << p.clip_frames << "\n"
      << "frame_interval_s: " << p.people.frame_interval_s << "\n"
      << "camera: \"" << p.camera().describe() << "\"\n"
      << "sensor:\n"
      << "  range_m: [" << s.min_range_m << ", " << s.max_range_m << "]\n"
      << "  baseline_m: " << s.baseline_m << "\n"
      << "  disparity_scale: " << s.disparity_scale << "\n"
      << "  noise_sigma_m: \"" << s.noise_per_m2 << " * z^2\"\n"
      << "  edge_hole_probability: {far: " << s.edge_far_hole << ", near: " << s.edge_near_hole << "}\n"
      << "  edge_fatten_probability: " << s.edge_fatten << "\n"
      << "  border_band_px_at_640x480: {left: " << s.band_left_px << ", right: " << s.band_right_px
      << ", top: " << s.band_top_px << ", bottom: " << s.band_bottom_px << "}\n"
      << "  eight_bit: {share: " << s.eight_bit_share << ", step_mm: [" << s.eight_bit_step_min_mm << ", "
      << s.eight_bit_step_max_mm << "], offset_m: [" << s.eight_bit_offset_min_m << ", " << s.eight_bit_offset_max_m << "]}\n"
      << "  coherent_holes_px: " << s.coherent_holes_px << "\n"
      << "  xtion: {share: " << s.xtion_share << ", noise_factor: [" << s.xtion_noise_min << ", " << s.xtion_noise_max << "]}\n"
      << "camera_pose:\n"
      << "  height_m: [" << r.camera_height_min_m << ", " << r.camera_height_max_m << "]\n"
      << "  pitch_deg: [" << r.pitch_min_deg << ", " << r.pitch_max_deg << "]\n"
      << "  roll_max_deg: " << r.roll_max_deg << "\n"
      << "  yaw_max_deg: " << r.yaw_max_deg << "\n"
      << "  moving: {share: " << r.moving_share << ", speed_max_mps: " << r.camera_speed_max_mps
      << ", turn_max_deg_s: " << r.camera_turn_max_deg_s << ", wobble_deg: " << r.camera_wobble_deg << "}\n"
      << "rooms:\n"
      << "  kinds: {on: " << on(r.room_kinds) << ", corridors: " << r.corridor_share << ", open_plan: " << r.open_plan_share << "}\n"
      << "  furniture: [" << r.furniture_min << ", " << r.furniture_max << "]\n"
      << "  clutter: {on: " << on(r.clutter) << ", pieces: [" << r.clutter_min << ", " << r.clutter_max << "]}\n"
      << "people_variety:\n"
      << "  bodies: {varied: " << on(b.varied_bodies) << ", children: " << b.child_share << "}\n"
      << "  outfits: " << on(b.outfits) << "\n"
      << "  poses: " << on(p.people.poses) << "\n"
      << "  sitting: " << p.people.sitting_share << "\n"
      << "  groups: " << p.people.group_share << "\n"
      << "  distance_m: [" << p.people.nearest_m << ", " << p.people.farthest_m << "]\n"
      << "  wall_clearance_m: " << p.people.clearance_m << "\n"
      << "boxes: \"boxes.csv: frame,person,x,y,w,h,visible_fraction,track (tight box of the visible pixels; "
         "person = track id)\"\n";
  return out.str();
}

void SynthWriter::commit(const std::string& command_line) {
  if (params_.fov_h_deg > 0) {  // a camera other than the scaled Kinect v1: readers take it from camera.yml
    AtomicTextFile camera((fs::path(dir_) / CameraFile::kFileName).string(), force_);
    camera.stream() << camera_file_text(CameraFile{params_.camera(), 1.0});
    camera.commit();
  }
  AtomicTextFile info((fs::path(dir_) / "synth.yml").string(), force_);
  info.stream() << describe(params_, command_line);
  info.commit();
  clips_->commit();
  boxes_->commit();
}

}  // namespace rdsf::synth
