#pragma once
// The model file: YAML written with cv::FileStorage, self-describing and versioned.
//
//   format: "rdsf-model"            format_version: 4 when the model states detection options, else 3
//                                   (1: no calibration, no trees; 2: no training.crops; all still read)
//   name, version (N of vN), created (ISO 8601 UTC)
//   feature_spec: canonical text, hash, name, and the numbers (window, cells or squares, bins)
//   training: recipe, backend, parameters, sample_sets (role, path, manifest_hash, available, used),
//             crops (format 3, when the sets record it: window_box, window_scale; candidates/crop_provenance.hpp),
//             train_positives/negatives, stopped, validation (source, counts, auc, tar_at_far_1/5,
//             error_rate, roc points, per-round figures each with its roc points)
//   classifier: bins (scheme uniform, count, min, max) and weak_classifiers, each
//             { kind: lut, feature, responses: [count values] } or
//             { kind: stump, feature, threshold, left, right } or (format 2)
//             { kind: tree, feature (the root's), nodes: [ {feature, responses}, ... ] } (breadth first)
//   calibration: (format 2) method platt|none, a, b, positives, negatives, source:
//             P(person) = 1 / (1 + exp(-(a H + b))); format 1 files read as method none (a = 2, b = 0)
//   operating_point: (format 3, optional) probability (0 < P < 1), rule: the P(person) at which the model
//             is read when the user gives no threshold (operating_point.hpp); absent: P >= 0.5
//   detection_options: (format 4, and only there) key: "text" for every option of the frame analyser
//             (analyser_parameters(): segmentation, candidates) the model was trained and measured with;
//             each key a known option, each text a value it accepts. A detector takes them for the options
//             its user does not give (pipeline/stated_options.hpp). A model stating none is written as
//             format 3, byte for byte as before, so a build that cannot apply them refuses only the models
//             that state them
//   opencv_model: (OpenCV backend only) the cv::ml::Boost exactly as it wrote itself
//
// Reading has one branch per known format version and refuses any other; it accepts every feature spec
// this build knows (features/feature_spec_record.hpp) and refuses unknown ones, and, when the caller names
// the spec it computes, a model whose spec differs; each message names the file and what differs.
#include <string>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/features/feature_spec.hpp"

namespace rdsf {

inline constexpr const char* kModelFormat = "rdsf-model";
inline constexpr int kModelFormatVersion = 3;  ///< the version written for a model that states no detection options
inline constexpr int kModelFormatVersionStated = 4;  ///< ... and for one that states them (the newest)

/// The file text of `model` (its name, version and created time included as they are set).
std::string model_file_text(const BoostedModel& model);

/// Reads a model file (any known format version, any known feature spec).
BoostedModel read_model_file(const std::string& path);
/// The same, refusing a model whose feature spec is not `expected` (the one the caller computes).
BoostedModel read_model_file(const std::string& path, const FeatureSpec& expected);

}  // namespace rdsf
