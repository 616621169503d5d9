#include "png_sequence.hpp"

#include <algorithm>
#include <filesystem>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace rdsf::openni_driver {
namespace {

const std::string kDepthSuffix = ".depth.png";
const std::string kColourSuffix = ".rgb.png";

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() > suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

bool PngSequence::open(const std::string& folder, std::string& error) {
  namespace fs = std::filesystem;
  folder_ = folder;
  stems_.clear();
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    error = folder + ": no such folder (the virtual sensor serves a folder of NAME.depth.png)";
    return false;
  }
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (ends_with(name, kDepthSuffix)) stems_.push_back(name.substr(0, name.size() - kDepthSuffix.size()));
  }
  if (ec) {
    error = folder + ": cannot list the folder (" + ec.message() + ")";
    return false;
  }
  if (stems_.empty()) {
    error = folder + ": no NAME.depth.png in the folder";
    return false;
  }
  std::sort(stems_.begin(), stems_.end());
  // A camera's colour stream sends every frame: colour is offered only when every frame has it.
  has_colour_ = true;
  for (std::size_t i = 0; i < stems_.size() && has_colour_; ++i) has_colour_ = fs::exists(colour_path(i), ec);
  const cv::Mat first = cv::imread(depth_path(0), cv::IMREAD_UNCHANGED);
  if (first.empty() || first.type() != CV_16UC1) {
    error = depth_path(0) + ": not a 16-bit single-channel PNG of depth in millimetres";
    return false;
  }
  width_px_ = first.cols;
  height_px_ = first.rows;
  return true;
}

std::string PngSequence::depth_path(std::size_t index) const {
  return (std::filesystem::path(folder_) / (stems_.at(index) + kDepthSuffix)).string();
}

std::string PngSequence::colour_path(std::size_t index) const {
  return (std::filesystem::path(folder_) / (stems_.at(index) + kColourSuffix)).string();
}

bool PngSequence::read_depth(std::size_t index, cv::Mat& depth_mm, std::string& error) const {
  depth_mm = cv::imread(depth_path(index), cv::IMREAD_UNCHANGED);
  if (depth_mm.empty() || depth_mm.type() != CV_16UC1) {
    error = depth_path(index) + ": not a 16-bit single-channel PNG of depth in millimetres";
    return false;
  }
  if (depth_mm.cols != width_px_ || depth_mm.rows != height_px_) {
    error = depth_path(index) + ": size differs from the first frame of the folder";
    return false;
  }
  return true;
}

bool PngSequence::read_rgb(std::size_t index, cv::Mat& rgb, std::string& error) const {
  const cv::Mat bgr = cv::imread(colour_path(index), cv::IMREAD_COLOR);
  if (bgr.empty()) {
    error = colour_path(index) + ": not a readable colour PNG";
    return false;
  }
  if (bgr.cols != width_px_ || bgr.rows != height_px_) {
    error = colour_path(index) + ": size differs from the depth frames (colour must be registered to depth)";
    return false;
  }
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  return true;
}

}  // namespace rdsf::openni_driver
