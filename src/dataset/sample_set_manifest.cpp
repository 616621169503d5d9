#include "rdsf/dataset/sample_set_manifest.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <opencv2/core.hpp>

#include "rdsf/core/atomic_file.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/yaml_guard.hpp"
#include "rdsf/features/feature_spec_record.hpp"

namespace rdsf {

std::string SampleSetManifest::to_text() const {
  cv::FileStorage fs(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  cv::write(fs, "format", std::string(kFormat));
  fs << "format_version" << kFormatVersion;
  fs << "feature_spec" << "{";
  cv::write(fs, "canonical", feature_spec.canonical());
  cv::write(fs, "hash", feature_spec.hash());
  cv::write(fs, "name", feature_spec.name());
  for (const auto& [key, value] : feature_spec_numbers(feature_spec)) fs << key << value;
  fs << "}";
  fs << "camera" << "{";
  fs << "width_px" << camera.width_px;
  fs << "height_px" << camera.height_px;
  fs << "fx_px" << camera.fx_px;
  fs << "fy_px" << camera.fy_px;
  fs << "cx_px" << camera.cx_px;
  fs << "cy_px" << camera.cy_px;
  fs << "}";
  if (crops.known()) {
    fs << "crops" << "{";
    cv::write(fs, "window_box", crops.window_box);
    fs << "window_scale" << crops.window_scale;
    fs << "}";
  }
  // Text through cv::write: `fs << text` would take a text starting with [ { ] } for a bracket.
  cv::write(fs, "created", created);
  cv::write(fs, "created_by", created_by);
  return fs.releaseAndGetString();
}

namespace {

SampleSetManifest parse_opened(const cv::FileStorage& fs, const std::string& path);

}  // namespace

SampleSetManifest SampleSetManifest::parse(const std::string& text, const std::string& path) {
  if (const std::string problem = yaml_layout_problem(text); !problem.empty()) {
    fail(path, problem + " (not a manifest this workbench wrote)");
  }
  cv::FileStorage fs;
  try {
    if (!fs.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML)) {
      fail(path, "is not a readable YAML manifest");
    }
  } catch (const Error&) {
    throw;
  } catch (const cv::Exception& e) {
    fail(path, "is not a readable YAML manifest (" + one_line(e.err) + ")");
  } catch (const std::exception& e) {
    // OpenCV's parser lets standard exceptions through (std::length_error on some damaged files).
    fail(path, "is not a readable YAML manifest (" + one_line(e.what()) + ")");
  }
  try {
    return parse_opened(fs, path);
  } catch (const Error& e) {
    // Messages may quote text from the file: keep them on one line.
    const std::string message = e.what();
    if (message.find_first_of("\n\r") == std::string::npos) throw;
    throw Error(one_line(message));
  } catch (const cv::Exception& e) {
    fail(path, "unreadable manifest (" + one_line(e.err) + ")");
  } catch (const std::exception& e) {
    fail(path, "unreadable manifest (" + one_line(e.what()) + ")");
  }
}

namespace {

SampleSetManifest parse_opened(const cv::FileStorage& fs, const std::string& path) {
  constexpr const char* kFormat = SampleSetManifest::kFormat;
  constexpr int kFormatVersion = SampleSetManifest::kFormatVersion;
  auto need = [&](const cv::FileNode& parent, const char* key) {
    if (!parent.isMap()) fail(path, std::string("missing entry '") + key + "' (its parent is not a mapping)");
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
  const std::string hash = need_string(spec, "hash");
  const std::string canonical = need_string(spec, "canonical");
  FeatureSpecNumbers numbers;  // optional beside the text; checked against it
  for (const char* key : {"window_width_px", "window_height_px", "cell_px", "rect_min_px", "rect_max_px",
                          "rect_step_px", "rect_stride_px", "bin_width_mm", "max_depth_mm"}) {
    if (!spec[key].empty()) numbers.emplace_back(key, need_int(spec, key));
  }
  try {
    m.feature_spec = feature_spec_from_record(canonical, hash, numbers);
  } catch (const Error& e) {
    fail(path, e.what());
  }
  const cv::FileNode camera = need(root, "camera");
  m.camera.width_px = need_int(camera, "width_px");
  m.camera.height_px = need_int(camera, "height_px");
  m.camera.fx_px = need_real(camera, "fx_px");
  m.camera.fy_px = need_real(camera, "fy_px");
  m.camera.cx_px = need_real(camera, "cx_px");
  m.camera.cy_px = need_real(camera, "cy_px");
  if (const cv::FileNode crops = root["crops"]; !crops.empty()) {
    m.crops.window_box = need_string(crops, "window_box");
    m.crops.window_scale = need_real(crops, "window_scale");
    if (!(m.crops.window_scale > 0.0)) fail(path, "entry 'window_scale' must be positive");
  }
  m.created = need_string(root, "created");
  const cv::FileNode by = root["created_by"];
  if (by.isString()) m.created_by = static_cast<std::string>(by);
  return m;
}

}  // namespace

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
