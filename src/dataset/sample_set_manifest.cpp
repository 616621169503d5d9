#include "dataset/sample_set_manifest.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <opencv2/core.hpp>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace rdsf {

std::string SampleSetManifest::to_text() const {
  cv::FileStorage fs(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  fs << "format" << kFormat;
  fs << "format_version" << kFormatVersion;
  fs << "feature_spec" << "{";
  fs << "canonical" << feature_spec.canonical();
  fs << "hash" << feature_spec.hash();
  fs << "window_width_px" << feature_spec.window_width_px;
  fs << "window_height_px" << feature_spec.window_height_px;
  fs << "cell_px" << feature_spec.cell_px;
  fs << "bin_width_mm" << feature_spec.bin_width_mm;
  fs << "max_depth_mm" << feature_spec.max_depth_mm;
  fs << "}";
  fs << "camera" << "{";
  fs << "width_px" << camera.width_px;
  fs << "height_px" << camera.height_px;
  fs << "fx_px" << camera.fx_px;
  fs << "fy_px" << camera.fy_px;
  fs << "cx_px" << camera.cx_px;
  fs << "cy_px" << camera.cy_px;
  fs << "}";
  fs << "created" << created;
  fs << "created_by" << created_by;
  return fs.releaseAndGetString();
}

SampleSetManifest SampleSetManifest::parse(const std::string& text, const std::string& path) {
  cv::FileStorage fs;
  try {
    if (!fs.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML)) {
      fail(path, "is not a readable YAML manifest");
    }
  } catch (const cv::Exception& e) {
    fail(path, "is not a readable YAML manifest (" + e.err + ")");
  }
  auto need = [&](const cv::FileNode& parent, const char* key) {
    const cv::FileNode node = parent[key];
    if (node.empty()) fail(path, std::string("missing entry '") + key + "'");
    return node;
  };
  auto need_int = [&](const cv::FileNode& parent, const char* key) {
    const cv::FileNode node = need(parent, key);
    if (!node.isInt()) fail(path, std::string("entry '") + key + "' must be an integer");
    return static_cast<int>(node);
  };
  auto need_real = [&](const cv::FileNode& parent, const char* key) {
    const cv::FileNode node = need(parent, key);
    if (!node.isInt() && !node.isReal()) fail(path, std::string("entry '") + key + "' must be a number");
    return static_cast<double>(node);
  };
  auto need_string = [&](const cv::FileNode& parent, const char* key) {
    const cv::FileNode node = need(parent, key);
    if (!node.isString()) fail(path, std::string("entry '") + key + "' must be text");
    return static_cast<std::string>(node);
  };
  const cv::FileNode root = fs.root();
  const std::string format = need_string(root, "format");
  if (format != kFormat) fail(path, "format is '" + format + "', expected '" + kFormat + "'");
  const int version = need_int(root, "format_version");
  if (version != kFormatVersion) {
    fail(path, "format_version " + std::to_string(version) + " is not supported (this program reads version " +
                   std::to_string(kFormatVersion) + ")");
  }
  SampleSetManifest m;
  const cv::FileNode spec = need(root, "feature_spec");
  m.feature_spec.window_width_px = need_int(spec, "window_width_px");
  m.feature_spec.window_height_px = need_int(spec, "window_height_px");
  m.feature_spec.cell_px = need_int(spec, "cell_px");
  m.feature_spec.bin_width_mm = need_int(spec, "bin_width_mm");
  m.feature_spec.max_depth_mm = need_int(spec, "max_depth_mm");
  try {
    m.feature_spec.validate();
  } catch (const Error& e) {
    fail(path, e.what());
  }
  const std::string hash = need_string(spec, "hash");
  const std::string canonical = need_string(spec, "canonical");
  if (canonical != m.feature_spec.canonical() || hash != m.feature_spec.hash()) {
    fail(path, "feature spec '" + canonical + "' (hash " + hash + ") does not match its parameters, which give '" +
                   m.feature_spec.canonical() + "' (hash " + m.feature_spec.hash() +
                   "): written by another version of the workbench?");
  }
  const cv::FileNode camera = need(root, "camera");
  m.camera.width_px = need_int(camera, "width_px");
  m.camera.height_px = need_int(camera, "height_px");
  m.camera.fx_px = need_real(camera, "fx_px");
  m.camera.fy_px = need_real(camera, "fy_px");
  m.camera.cx_px = need_real(camera, "cx_px");
  m.camera.cy_px = need_real(camera, "cy_px");
  m.created = need_string(root, "created");
  const cv::FileNode by = root["created_by"];
  if (by.isString()) m.created_by = static_cast<std::string>(by);
  return m;
}

SampleSetManifest SampleSetManifest::read(const std::string& path, std::string* text_out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be opened (is this a sample set folder?)");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  SampleSetManifest m = parse(text, path);
  if (text_out != nullptr) *text_out = text;
  return m;
}

void SampleSetManifest::write(const std::string& path) const {
  AtomicTextFile file(path, /*overwrite=*/false);
  file.stream() << to_text();
  file.commit();
}

}  // namespace rdsf
