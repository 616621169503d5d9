#pragma once
// Frames from 16-bit depth PNGs in millimetres: a folder of NAME.depth.png (sorted by name), a list file
// of such paths, or one file. NAME.rgb.png beside a depth image is its registered colour.
#include <string>
#include <vector>

#include "rdsf/frame/frame_source.hpp"

namespace rdsf {

class PngFolderSource : public FrameSource {
 public:
  /// `spec` is a folder, a list file or a single NAME.depth.png; throws Error when it holds no frames.
  PngFolderSource(const std::string& spec, const CameraModel& camera);

  bool next(DepthFrame& frame) override;
  std::string description() const override;
  std::optional<std::int64_t> frame_count() const override {
    return static_cast<std::int64_t>(depth_paths_.size());
  }

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
  std::size_t next_ = 0;
};

}  // namespace rdsf
