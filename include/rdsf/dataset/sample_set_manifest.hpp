#pragma once
// manifest.yml of a sample set (cv::FileStorage YAML): the format name and version, the feature spec
// (canonical text, hash and parameters), the camera model of the frames the crops were cut from, how the
// crops were cut (crops: window_box, window_scale; optional, absent in sets written before it was recorded
// and in thesis text imports), the frame analyser's options its candidates were found with
// (analyser_options: key: "text" for every option, written by rdsf-mine and rdsf-label since 2026-12-06;
// optional, absent before and in imports), and when and by what the set was created. Written once,
// atomically, when the set is created; never changed.
#include <string>

#include "rdsf/candidates/crop_provenance.hpp"
#include "rdsf/core/parameter_table.hpp"
#include "rdsf/features/feature_spec.hpp"
#include "rdsf/frame/camera_model.hpp"

namespace rdsf {

struct SampleSetManifest {
  static constexpr const char* kFormat = "rdsf-sample-set";
  static constexpr int kFormatVersion = 1;

  FeatureSpec feature_spec;
  CameraModel camera;
  CropProvenance crops;    ///< unknown (not written) unless the writer knew it
  /// The analyser options the candidates were found with, (key, text) of every analyser option; empty: not
  /// recorded. rdsf-train states them in the model when every set it reads records the same.
  RecordedParameters analyser_options;
  std::string created;     ///< ISO 8601 UTC
  std::string created_by;  ///< program that created the set ("rdsf-mine")

  /// The YAML text.
  std::string to_text() const;
  /// Parses `text` read from `path`; throws Error naming `path` on a wrong format, version, or a feature
  /// spec hash that does not match its parameters.
  static SampleSetManifest parse(const std::string& text, const std::string& path);
  /// Reads and parses the file; `text_out` (optional) receives its bytes.
  static SampleSetManifest read(const std::string& path, std::string* text_out = nullptr);
  /// Writes the file through a temporary name; refuses to replace an existing one.
  void write(const std::string& path) const;
};

}  // namespace rdsf
