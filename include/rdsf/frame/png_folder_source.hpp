#pragma once
// Frames from 16-bit depth PNGs in millimetres: a folder of NAME.depth.png (sorted by name), a list file
// of such paths, or one file. NAME.rgb.png beside a depth image is its registered colour.
// camera.yml beside the frames (the folder's, the list file's folder's, the single file's folder's;
// rdsf/frame/camera_file.hpp) is their camera model and depth unit: it wins over the given model unless that
// was given by the user (FrameSourceOptions::camera_given), and a frame of another size is an Error.
// Without it frames carry the given model, rescaled to their size.
#include <optional>
#include <string>
#include <vector>

#include "rdsf/frame/camera_file.hpp"
#include "rdsf/frame/frame_source.hpp"

namespace rdsf {

class PngFolderSource : public FrameSource {
 public:
  /// `spec` is a folder, a list file or a single NAME.depth.png; throws Error when it holds no frames.
  PngFolderSource(const std::string& spec, const CameraModel& camera);
  /// The same with the options' camera model (and whether the user gave it).
  PngFolderSource(const std::string& spec, const FrameSourceOptions& options);

  bool next(DepthFrame& frame) override;
  /// read_frame(i) of the next frame i, deferred.
  bool next_deferred(FrameDecode& decode) override;
  std::string description() const override;
  std::optional<std::int64_t> frame_count() const override {
    return static_cast<std::int64_t>(depth_paths_.size());
  }
  /// frame_name() of every depth path.
  std::optional<std::vector<std::string>> frame_names() const override;

  /// Frame `i` (0-based, < frame_count()) as next() delivers it; safe to call from several threads at once.
  DepthFrame read_frame(std::size_t i) const;

  /// The camera.yml in force (its path in camera_file_path()), or nothing.
  const std::optional<CameraFile>& camera_file() const { return file_; }
  const std::string& camera_file_path() const { return file_path_; }

  /// The depth image paths in the order they are delivered.
  const std::vector<std::string>& depth_paths() const { return depth_paths_; }

  /// "lab_alberto1" for ".../lab_alberto1.depth.png".
  static std::string frame_name(const std::string& depth_path);
  /// The colour image that goes with a depth image: ".../NAME.rgb.png" for ".../NAME.depth.png" (it may not
  /// exist); empty for a path not named NAME.depth.png.
  static std::string colour_path(const std::string& depth_path);

 private:
  std::string spec_;
  std::vector<std::string> depth_paths_;
  CameraModel camera_;
  bool camera_given_ = false;
  std::optional<CameraFile> file_;
  std::string file_path_;
  std::size_t next_ = 0;
};

}  // namespace rdsf
