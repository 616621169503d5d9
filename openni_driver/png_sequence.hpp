#pragma once
// The frames a virtual sensor serves: every NAME.depth.png of a folder (16-bit, millimetres), sorted by
// name, with NAME.rgb.png as registered colour when every frame has one (a camera's colour stream sends
// every frame; a folder with colour for some frames only is served as depth only).
// This is the driver's own small reader: the driver is a shared library loaded by OpenNI2 and does not
// link the workbench's core library.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf::openni_driver {

class PngSequence {
 public:
  /// Lists `folder`. Returns false and sets `error` (one line naming the folder or file) when the folder
  /// is missing, holds no NAME.depth.png, or its first frame is not a 16-bit single-channel PNG.
  bool open(const std::string& folder, std::string& error);

  std::size_t size() const { return stems_.size(); }
  bool has_colour() const { return has_colour_; }
  int width_px() const { return width_px_; }
  int height_px() const { return height_px_; }
  const std::string& folder() const { return folder_; }

  /// Reads frame `index` as depth in millimetres (CV_16UC1, the size of the first frame).
  bool read_depth(std::size_t index, cv::Mat& depth_mm, std::string& error) const;
  /// Reads frame `index` as colour in RGB byte order (CV_8UC3, the size of the first frame).
  bool read_rgb(std::size_t index, cv::Mat& rgb, std::string& error) const;

 private:
  std::string depth_path(std::size_t index) const;
  std::string colour_path(std::size_t index) const;

  std::string folder_;
  std::vector<std::string> stems_;
  bool has_colour_ = false;
  int width_px_ = 0;
  int height_px_ = 0;
};

}  // namespace rdsf::openni_driver
