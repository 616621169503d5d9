#include "rdsf/frame/png_folder_source.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "rdsf/core/error.hpp"
#include "rdsf/frame/depth_png.hpp"

namespace fs = std::filesystem;

namespace rdsf {
namespace {

const std::string kDepthSuffix = ".depth.png";
const std::string kColourSuffix = ".rgb.png";

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> list_folder(const std::string& folder) {
  std::vector<std::string> paths;
  std::size_t other_pngs = 0;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (ends_with(name, kDepthSuffix)) {
      paths.push_back(entry.path().string());
    } else if (ends_with(name, ".png")) {
      ++other_pngs;
    }
  }
  if (ec) fail(folder, "cannot list folder: " + ec.message());
  std::sort(paths.begin(), paths.end());
  if (paths.empty() && other_pngs > 0) {  // another dataset's layout (depth/000001.png ...): say how to read it
    fail(folder, "folder holds no *" + kDepthSuffix + " frames (its " + std::to_string(other_pngs) +
                     " other PNG files are not taken for depth: give a list file of the depth images, one path a "
                     "line, e.g. ls " + folder + "/*.png > frames.txt)");
  }
  if (paths.empty()) fail(folder, "folder holds no *" + kDepthSuffix + " frames");
  return paths;
}

std::vector<std::string> read_list_file(const std::string& list_path) {
  std::ifstream in(list_path);
  if (!in) fail(list_path, "cannot be opened for reading");
  const fs::path base = fs::path(list_path).parent_path();
  std::vector<std::string> paths;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    line = trim(line);
    if (line.empty() || line[0] == '#') continue;
    if (line.find('\0') != std::string::npos || !ends_with(line, ".png")) {
      fail(list_path, "line " + std::to_string(line_number) +
                          ": not a PNG path (a list file names one NAME.depth.png a line)");
    }
    fs::path path(line);
    if (path.is_relative()) path = base / path;
    paths.push_back(path.string());
  }
  if (paths.empty()) fail(list_path, "list file names no frames");
  return paths;
}

}  // namespace

PngFolderSource::PngFolderSource(const std::string& spec, const CameraModel& camera)
    : PngFolderSource(spec, FrameSourceOptions{camera, false, {}, {}}) {}

PngFolderSource::PngFolderSource(const std::string& spec, const FrameSourceOptions& options)
    : spec_(spec), camera_(options.camera), camera_given_(options.camera_given) {
  std::error_code ec;
  if (!fs::exists(spec, ec)) fail(spec, "no such file or folder");
  fs::path folder;
  if (fs::is_directory(spec, ec)) {
    depth_paths_ = list_folder(spec);
    folder = spec;
  } else if (ends_with(spec, ".png")) {
    depth_paths_ = {spec};
    folder = fs::path(spec).parent_path();
  } else {
    depth_paths_ = read_list_file(spec);
    folder = fs::path(spec).parent_path();
  }
  const fs::path camera_file = folder / CameraFile::kFileName;
  if (fs::exists(camera_file, ec)) {
    file_path_ = camera_file.string();
    file_ = read_camera_file(file_path_);
  }
}

std::string PngFolderSource::frame_name(const std::string& depth_path) {
  std::string name = fs::path(depth_path).filename().string();
  if (ends_with(name, kDepthSuffix)) return name.substr(0, name.size() - kDepthSuffix.size());
  if (ends_with(name, ".png")) return name.substr(0, name.size() - 4);
  return name;
}

std::optional<std::vector<std::string>> PngFolderSource::frame_names() const {
  std::vector<std::string> names;
  names.reserve(depth_paths_.size());
  for (const std::string& path : depth_paths_) names.push_back(frame_name(path));
  return names;
}

std::string PngFolderSource::colour_path(const std::string& depth_path) {
  if (!ends_with(depth_path, kDepthSuffix)) return {};
  return depth_path.substr(0, depth_path.size() - kDepthSuffix.size()) + kColourSuffix;
}

bool PngFolderSource::next(DepthFrame& frame) {
  if (next_ >= depth_paths_.size()) return false;
  frame = read_frame(next_);
  ++next_;
  return true;
}

bool PngFolderSource::next_deferred(FrameDecode& decode) {
  if (next_ >= depth_paths_.size()) return false;
  const std::size_t i = next_++;
  decode = [this, i] { return read_frame(i); };
  return true;
}

DepthFrame PngFolderSource::read_frame(std::size_t i) const {
  const std::string& depth_path = depth_paths_.at(i);
  DepthFrame frame;
  frame.depth_mm = read_depth_png(depth_path);
  const cv::Size size = frame.depth_mm.size();
  if (file_ && (size.width != file_->camera.width_px || size.height != file_->camera.height_px)) {
    fail(depth_path, "frame is " + std::to_string(size.width) + "x" + std::to_string(size.height) + ", " +
                         file_path_ + " says " + std::to_string(file_->camera.width_px) + "x" +
                         std::to_string(file_->camera.height_px));
  }
  if (file_ && file_->depth_unit_mm != 1.0) {  // stored units to millimetres, nearest; beyond 65535 mm: none
    frame.depth_mm.forEach([unit = file_->depth_unit_mm](std::uint16_t& v, const int*) {
      const double mm = std::nearbyint(v * unit);
      v = mm <= 65535 ? static_cast<std::uint16_t>(mm) : 0;
    });
  }
  const std::string colour = colour_path(depth_path);
  std::error_code ec;
  if (!colour.empty() && fs::exists(colour, ec)) frame.bgr = read_colour_png(colour, size);
  frame.index = static_cast<std::int64_t>(i);
  frame.name = frame_name(depth_path);
  frame.timestamp_us = frame.index * kFrameIntervalUs;  // image folders carry no clock: 30 frames per second
  const CameraModel& model = file_ && !camera_given_ ? file_->camera : camera_;
  frame.camera = (size.width == model.width_px && size.height == model.height_px)
                     ? model
                     : model.scaled_to(size.width, size.height);
  return frame;
}

std::string PngFolderSource::description() const {
  std::string text = spec_ + " (" + std::to_string(depth_paths_.size()) + " frames)";
  if (file_) {
    text += camera_given_ ? ", camera model given (" + file_path_ + " not used)"
                          : ", camera model from " + file_path_ + " (" + file_->camera.describe() + ")";
  }
  return text;
}

}  // namespace rdsf
