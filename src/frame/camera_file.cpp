#include "rdsf/frame/camera_file.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include <opencv2/core.hpp>

#include "rdsf/core/error.hpp"
#include "rdsf/core/yaml_guard.hpp"

namespace rdsf {
namespace {

CameraFile parse_opened(const cv::FileStorage& fs, const std::string& path) {
  const cv::FileNode root = fs.root();
  if (!root.isMap()) fail(path, "is not a camera.yml (no mapping at the top)");
  auto need = [&](const char* key) {
    const cv::FileNode node = root[key];
    if (node.empty()) fail(path, std::string("missing entry '") + key + "'");
    return node;
  };
  auto need_int = [&](const char* key) {
    const cv::FileNode node = need(key);
    if (!node.isInt()) fail(path, std::string("entry '") + key + "' must be an integer");
    return static_cast<int>(node);
  };
  auto need_real = [&](const cv::FileNode& node, const char* key) {
    if (!node.isInt() && !node.isReal()) fail(path, std::string("entry '") + key + "' must be a number");
    const double value = static_cast<double>(node);
    if (!std::isfinite(value)) fail(path, std::string("entry '") + key + "' must be finite");
    return value;
  };
  const cv::FileNode format = need("format");
  if (!format.isString() || static_cast<std::string>(format) != CameraFile::kFormat) {
    fail(path, std::string("format must be '") + CameraFile::kFormat + "'");
  }
  const int version = need_int("format_version");
  if (version != CameraFile::kFormatVersion) {
    fail(path, "format_version " + std::to_string(version) + " is not supported (this program reads version " +
                   std::to_string(CameraFile::kFormatVersion) + ")");
  }
  CameraFile file;
  CameraModel& c = file.camera;
  c.width_px = need_int("width_px");
  c.height_px = need_int("height_px");
  if (c.width_px < 1 || c.width_px > 16384 || c.height_px < 1 || c.height_px > 16384) {
    fail(path, "image size " + std::to_string(c.width_px) + "x" + std::to_string(c.height_px) +
                   " is not within 1..16384 px");
  }
  c.fx_px = need_real(need("fx_px"), "fx_px");
  c.fy_px = need_real(need("fy_px"), "fy_px");
  c.cx_px = need_real(need("cx_px"), "cx_px");
  c.cy_px = need_real(need("cy_px"), "cy_px");
  if (!(c.fx_px > 0) || !(c.fy_px > 0)) fail(path, "focal lengths fx_px and fy_px must be positive");
  if (c.cx_px < -0.5 || c.cx_px > c.width_px - 0.5 || c.cy_px < -0.5 || c.cy_px > c.height_px - 0.5) {
    fail(path, "principal point (cx_px, cy_px) lies outside the image");
  }
  if (const cv::FileNode unit = root["depth_unit_mm"]; !unit.empty()) {
    file.depth_unit_mm = need_real(unit, "depth_unit_mm");
    if (!(file.depth_unit_mm > 0 && file.depth_unit_mm <= 100)) fail(path, "depth_unit_mm must be in (0, 100]");
  }
  return file;
}

}  // namespace

CameraFile parse_camera_file(const std::string& text, const std::string& path) {
  if (const std::string problem = yaml_layout_problem(text); !problem.empty()) fail(path, problem);
  cv::FileStorage fs;
  try {
    if (!fs.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML)) {
      fail(path, "is not readable YAML");
    }
    return parse_opened(fs, path);
  } catch (const Error& e) {
    throw Error(one_line(e.what()));
  } catch (const cv::Exception& e) {
    fail(path, "is not readable YAML (" + one_line(e.err) + ")");
  } catch (const std::exception& e) {  // OpenCV's parser lets standard exceptions through
    fail(path, "is not readable YAML (" + one_line(e.what()) + ")");
  }
}

CameraFile read_camera_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be opened for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_camera_file(text.str(), path);
}

std::string camera_file_text(const CameraFile& file) {
  cv::FileStorage fs(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  cv::write(fs, "format", std::string(CameraFile::kFormat));
  fs << "format_version" << CameraFile::kFormatVersion;
  fs << "width_px" << file.camera.width_px;
  fs << "height_px" << file.camera.height_px;
  fs << "fx_px" << file.camera.fx_px;
  fs << "fy_px" << file.camera.fy_px;
  fs << "cx_px" << file.camera.cx_px;
  fs << "cy_px" << file.camera.cy_px;
  fs << "depth_unit_mm" << file.depth_unit_mm;
  return fs.releaseAndGetString();
}

}  // namespace rdsf
