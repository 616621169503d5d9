#include "rdsf/dataset/sample_set_manifest.hpp"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <opencv2/core.hpp>

#include "rdsf/core/atomic_file.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/yaml_reader.hpp"
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
  if (!analyser_options.empty()) {
    fs << "analyser_options" << "{";
    for (const auto& [key, value] : analyser_options) cv::write(fs, key, value);
    fs << "}";
  }
  // Text through cv::write: `fs << text` would take a text starting with [ { ] } for a bracket.
  cv::write(fs, "created", created);
  cv::write(fs, "created_by", created_by);
  return fs.releaseAndGetString();
}

namespace {

SampleSetManifest parse_opened(const YamlReader& r) {
  constexpr const char* kFormat = SampleSetManifest::kFormat;
  constexpr int kFormatVersion = SampleSetManifest::kFormatVersion;
  const cv::FileNode root = r.root();
  const std::string format = r.text(root, "format");
  if (format != kFormat) r.bad("format is '" + format + "', expected '" + kFormat + "'");
  const int version = r.integer(root, "format_version");
  if (version != kFormatVersion) {
    r.bad("format_version " + std::to_string(version) + " is not supported (this program reads version " +
          std::to_string(kFormatVersion) + ")");
  }
  SampleSetManifest m;
  const cv::FileNode spec = r.need(root, "feature_spec");
  const std::string hash = r.text(spec, "hash", "feature_spec.");
  const std::string canonical = r.text(spec, "canonical", "feature_spec.");
  FeatureSpecNumbers numbers;  // optional beside the text; checked against it
  for (const char* key : {"window_width_px", "window_height_px", "cell_px", "rect_min_px", "rect_max_px",
                          "rect_step_px", "rect_stride_px", "bin_width_mm", "max_depth_mm"}) {
    if (r.has(spec, key)) numbers.emplace_back(key, r.integer(spec, key, "feature_spec."));
  }
  try {
    m.feature_spec = feature_spec_from_record(canonical, hash, numbers);
  } catch (const Error& e) {
    r.bad(e.what());
  }
  const cv::FileNode camera = r.need(root, "camera");
  m.camera.width_px = r.integer(camera, "width_px", "camera.");
  m.camera.height_px = r.integer(camera, "height_px", "camera.");
  m.camera.fx_px = r.real(camera, "fx_px", "camera.");
  m.camera.fy_px = r.real(camera, "fy_px", "camera.");
  m.camera.cx_px = r.real(camera, "cx_px", "camera.");
  m.camera.cy_px = r.real(camera, "cy_px", "camera.");
  if (r.has(root, "crops")) {
    const cv::FileNode crops = root["crops"];
    m.crops.window_box = r.text(crops, "window_box", "crops.");
    m.crops.window_scale = r.real(crops, "window_scale", "crops.");
    if (!(m.crops.window_scale > 0.0)) r.bad("'crops.window_scale' must be positive");
  }
  if (r.has(root, "analyser_options")) {
    const cv::FileNode options = root["analyser_options"];
    if (!options.isMap()) r.bad("'analyser_options' must be a mapping of options to values");
    for (auto it = options.begin(); it != options.end(); ++it) {
      const std::string key = (*it).name();
      const bool name = !key.empty() && std::islower(static_cast<unsigned char>(key[0])) != 0 &&
                        key.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") == std::string::npos;
      if (!name) r.bad("'analyser_options' holds '" + one_line(key) + "', which is no option's name");
      m.analyser_options.emplace_back(key, r.text(options, key, "analyser_options."));
    }
  }
  m.created = r.text(root, "created");
  m.created_by = YamlReader::opt_text(YamlReader::child(root, "created_by"));
  return m;
}

}  // namespace

SampleSetManifest SampleSetManifest::parse(const std::string& text, const std::string& path) {
  const YamlReader r(text, path, "manifest");
  return r.read(parse_opened);
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
