#include "rdsf/classifier/model_file.hpp"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <ctime>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <utility>

#include <opencv2/core.hpp>

#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/classifier/yaml_node_copy.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/yaml_reader.hpp"
#include "rdsf/features/feature_spec_record.hpp"

namespace rdsf {
namespace {

using cv::FileNode;
using cv::FileStorage;

/// A key cv::FileStorage accepts when writing: a letter or '_' first, then letters, digits, '-', '_', ' '.
/// Keys read back from a file (free-form training parameters) may be anything the YAML reader accepted.
std::string writable_key(const std::string& key) {
  std::string out = key.empty() ? "_" : key;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(out[i]);
    const bool ok = std::isalpha(c) != 0 || c == '_' || (i > 0 && (std::isdigit(c) != 0 || c == '-' || c == ' '));
    if (!ok) out[i] = '_';
  }
  return out;
}

void write_feature_spec(FileStorage& fs, const FeatureSpec& spec) {
  fs.startWriteStruct("feature_spec", FileNode::MAP);
  cv::write(fs, "canonical", spec.canonical());
  cv::write(fs, "hash", spec.hash());
  cv::write(fs, "name", spec.name());
  for (const auto& [key, value] : feature_spec_numbers(spec)) cv::write(fs, key, value);
  cv::write(fs, "dimension", spec.dimension());
  fs.endWriteStruct();
}

/// A one-line map of numbers, {key: value, ...} in the order given (ROC and probability points).
void write_flow_reals(FileStorage& fs, std::initializer_list<std::pair<const char*, double>> entries) {
  fs.startWriteStruct("", FileNode::MAP | FileNode::FLOW);
  for (const auto& [key, value] : entries) cv::write(fs, key, value);
  fs.endWriteStruct();
}

void write_roc_point(FileStorage& fs, const RocPoint& p) {
  write_flow_reals(fs, {{"far", p.far}, {"tar", p.tar}, {"threshold", p.threshold}});
}

/// The sequence `key` holding `write_one`'s writing of each item, in order.
template <typename T, typename Write>
void write_each(FileStorage& fs, const char* key, const std::vector<T>& items, Write write_one) {
  fs.startWriteStruct(key, FileNode::SEQ);
  for (const T& item : items) write_one(fs, item);
  fs.endWriteStruct();
}

void write_sample_set_use(FileStorage& fs, const SampleSetUse& s) {
  fs.startWriteStruct("", FileNode::MAP | FileNode::FLOW);
  cv::write(fs, "role", s.role);
  cv::write(fs, "path", s.path);
  cv::write(fs, "manifest_hash", s.manifest_hash);
  cv::write(fs, "available", static_cast<int>(s.available));
  cv::write(fs, "used", static_cast<int>(s.used));
  fs.endWriteStruct();
}

void write_probability_point(FileStorage& fs, const ProbabilityPoint& p) {
  write_flow_reals(fs, {{"probability", p.probability}, {"tar", p.tar}, {"far", p.far}});
}

void write_round_figures(FileStorage& fs, const RoundFigures& r) {
  fs.startWriteStruct("", FileNode::MAP);
  cv::write(fs, "round", r.round);
  cv::write(fs, "feature", r.feature);
  cv::write(fs, "train_error", r.train_error);
  cv::write(fs, "validation_error", r.validation.error_rate);
  cv::write(fs, "auc", r.validation.auc);
  cv::write(fs, "tar_at_far_1", r.validation.tar_at_far_1);
  cv::write(fs, "tar_at_far_5", r.validation.tar_at_far_5);
  write_each(fs, "roc", r.roc, write_roc_point);
  fs.endWriteStruct();
}

void write_validation_figures(FileStorage& fs, const ValidationFigures& v) {
  fs.startWriteStruct("validation", FileNode::MAP);
  cv::write(fs, "source", v.source);
  cv::write(fs, "positives", static_cast<int>(v.positives));
  cv::write(fs, "negatives", static_cast<int>(v.negatives));
  cv::write(fs, "auc", v.summary.auc);
  cv::write(fs, "tar_at_far_1", v.summary.tar_at_far_1);
  cv::write(fs, "tar_at_far_5", v.summary.tar_at_far_5);
  cv::write(fs, "error_rate", v.summary.error_rate);
  write_each(fs, "roc", v.roc, write_roc_point);
  write_each(fs, "by_probability", v.by_probability, write_probability_point);
  write_each(fs, "rounds", v.rounds, write_round_figures);
  fs.endWriteStruct();
}

void write_training(FileStorage& fs, const TrainingRecord& t) {
  fs.startWriteStruct("training", FileNode::MAP);
  cv::write(fs, "recipe", t.recipe);
  cv::write(fs, "backend", t.backend);
  fs.startWriteStruct("parameters", FileNode::MAP);
  for (const auto& [key, value] : t.parameters) cv::write(fs, writable_key(key), value);
  fs.endWriteStruct();
  write_each(fs, "sample_sets", t.sample_sets, write_sample_set_use);
  if (t.crops.known()) {
    fs.startWriteStruct("crops", FileNode::MAP);
    cv::write(fs, "window_box", t.crops.window_box);
    cv::write(fs, "window_scale", t.crops.window_scale);
    fs.endWriteStruct();
  }
  cv::write(fs, "train_positives", static_cast<int>(t.train_positives));
  cv::write(fs, "train_negatives", static_cast<int>(t.train_negatives));
  cv::write(fs, "stopped", t.stopped);
  write_validation_figures(fs, t.validation);
  fs.endWriteStruct();
}

void write_classifier(FileStorage& fs, const BoostedModel& model) {
  fs.startWriteStruct("classifier", FileNode::MAP);
  fs.startWriteStruct("bins", FileNode::MAP | FileNode::FLOW);
  cv::write(fs, "scheme", std::string("uniform"));
  cv::write(fs, "count", model.bins().count);
  cv::write(fs, "min", static_cast<double>(model.bins().min_value));
  cv::write(fs, "max", static_cast<double>(model.bins().max_value));
  fs.endWriteStruct();
  cv::write(fs, "weak_count", static_cast<int>(model.weak_classifiers().size()));
  fs.startWriteStruct("weak_classifiers", FileNode::SEQ);
  for (const WeakClassifier& w : model.weak_classifiers()) {
    fs.startWriteStruct("", FileNode::MAP);
    if (w.kind == WeakClassifier::Kind::Lut) {
      cv::write(fs, "kind", std::string("lut"));
      cv::write(fs, "feature", w.feature);
      cv::write(fs, "responses", w.responses);
    } else if (w.kind == WeakClassifier::Kind::Tree) {
      cv::write(fs, "kind", std::string("tree"));
      cv::write(fs, "feature", w.feature);
      fs.startWriteStruct("nodes", FileNode::SEQ);
      for (const LutNode& node : w.nodes) {
        fs.startWriteStruct("", FileNode::MAP);
        cv::write(fs, "feature", node.feature);
        cv::write(fs, "responses", node.responses);
        fs.endWriteStruct();
      }
      fs.endWriteStruct();
    } else {
      cv::write(fs, "kind", std::string("stump"));
      cv::write(fs, "feature", w.feature);
      cv::write(fs, "threshold", w.threshold);
      cv::write(fs, "left", w.left);
      cv::write(fs, "right", w.right);
    }
    fs.endWriteStruct();
  }
  fs.endWriteStruct();
  fs.endWriteStruct();
}

void write_calibration(FileStorage& fs, const ScoreCalibration& c) {
  fs.startWriteStruct("calibration", FileNode::MAP);
  cv::write(fs, "method", c.method);
  cv::write(fs, "a", c.a);
  cv::write(fs, "b", c.b);
  cv::write(fs, "positives", static_cast<int>(c.positives));
  cv::write(fs, "negatives", static_cast<int>(c.negatives));
  cv::write(fs, "source", c.source);
  fs.endWriteStruct();
}

// Written only when the model states one: a model without it keeps its bytes.
void write_operating_point(FileStorage& fs, const std::optional<OperatingPoint>& point) {
  if (!point) return;
  fs.startWriteStruct("operating_point", FileNode::MAP);
  cv::write(fs, "probability", point->probability);
  cv::write(fs, "rule", point->rule);
  fs.endWriteStruct();
}

// Written only when the model states them (format 4): (key, text) pairs as the analyser table's rows.
void write_detection_options(FileStorage& fs, const RecordedParameters& options) {
  if (options.empty()) return;
  fs.startWriteStruct("detection_options", FileNode::MAP);
  for (const auto& [key, value] : options) cv::write(fs, writable_key(key), value);
  fs.endWriteStruct();
}

// ---- reading ----


// Any spec this build knows; `expected` (when given) is the one the caller computes.
FeatureSpec read_feature_spec_v1(const YamlReader& r, const FileNode& root, const FeatureSpec* expected) {
  const FileNode node = r.need(root, "feature_spec", "");
  const std::string canonical = r.text(node, "canonical", "feature_spec.");
  const std::string hash = r.text(node, "hash", "feature_spec.");
  FeatureSpecNumbers numbers;  // optional beside the text; checked against it
  for (const char* key : {"window_width_px", "window_height_px", "cell_px", "rect_min_px", "rect_max_px",
                          "rect_step_px", "rect_stride_px", "bin_width_mm", "max_depth_mm"}) {
    if (node.isMap() && !node[key].empty()) numbers.emplace_back(key, r.integer(node, key, "feature_spec."));
  }
  FeatureSpec spec;
  try {
    spec = feature_spec_from_record(canonical, hash, numbers);
  } catch (const Error& e) {
    r.bad(e.what());
  }
  if (expected != nullptr && spec != *expected) {
    r.bad("feature spec differs: the model was trained on '" + canonical + "' (hash " + hash +
          "), this build computes '" + expected->canonical() + "' (hash " + expected->hash() + ")");
  }
  return spec;
}

/// What `read_one` makes of each element of the sequence `node`, in order (none when it is no sequence).
template <typename Read>
auto read_each(const FileNode& node, Read read_one) -> std::vector<decltype(read_one(node))> {
  std::vector<decltype(read_one(node))> out;
  if (!node.isSeq()) return out;
  for (auto it = node.begin(); it != node.end(); ++it) out.push_back(read_one(*it));
  return out;
}

// The training record's entries are informational: read leniently (YamlReader::opt_*), a missing one 0.
double real_at(const FileNode& map, const char* key) { return YamlReader::opt_real(YamlReader::child(map, key)); }
int int_at(const FileNode& map, const char* key) { return YamlReader::opt_int(YamlReader::child(map, key)); }
std::string text_at(const FileNode& map, const char* key) { return YamlReader::opt_text(YamlReader::child(map, key)); }

/// The figures of a RocSummary from the map `node`; the error rate under `error_key` (the final model's
/// "error_rate", a round's "validation_error").
RocSummary read_roc_summary(const FileNode& node, const char* error_key) {
  RocSummary s;
  s.auc = real_at(node, "auc");
  s.tar_at_far_1 = real_at(node, "tar_at_far_1");
  s.tar_at_far_5 = real_at(node, "tar_at_far_5");
  s.error_rate = real_at(node, error_key);
  return s;
}

std::vector<RocPoint> read_roc_points(const FileNode& node) {
  return read_each(node, [](const FileNode& p) {
    return RocPoint{real_at(p, "far"), real_at(p, "tar"), real_at(p, "threshold")};
  });
}

SampleSetUse read_sample_set_use(const FileNode& s) {
  SampleSetUse use;
  use.role = text_at(s, "role");
  use.path = text_at(s, "path");
  use.manifest_hash = text_at(s, "manifest_hash");
  use.available = static_cast<std::size_t>(int_at(s, "available"));
  use.used = static_cast<std::size_t>(int_at(s, "used"));
  return use;
}

RoundFigures read_round_figures(const FileNode& p) {
  RoundFigures r;
  r.round = int_at(p, "round");
  r.feature = int_at(p, "feature");
  r.train_error = real_at(p, "train_error");
  r.validation = read_roc_summary(p, "validation_error");
  r.roc = read_roc_points(YamlReader::child(p, "roc"));
  return r;
}

ValidationFigures read_validation_figures(const FileNode& v) {
  ValidationFigures f;
  f.source = text_at(v, "source");
  f.positives = static_cast<std::size_t>(int_at(v, "positives"));
  f.negatives = static_cast<std::size_t>(int_at(v, "negatives"));
  f.summary = read_roc_summary(v, "error_rate");
  f.roc = read_roc_points(YamlReader::child(v, "roc"));
  f.rounds = read_each(YamlReader::child(v, "rounds"), read_round_figures);
  f.by_probability = read_each(YamlReader::child(v, "by_probability"), [](const FileNode& p) {
    return ProbabilityPoint{real_at(p, "probability"), real_at(p, "tar"), real_at(p, "far")};
  });
  return f;
}

TrainingRecord read_training_v1(const FileNode& node) {
  TrainingRecord t;
  if (!node.isMap()) return t;
  t.recipe = text_at(node, "recipe");
  t.backend = text_at(node, "backend");
  const FileNode params = YamlReader::child(node, "parameters");
  if (params.isMap()) {
    for (auto it = params.begin(); it != params.end(); ++it) {
      const FileNode p = *it;
      std::string value = p.isString() ? static_cast<std::string>(p) : "";
      if (p.isInt()) value = std::to_string(static_cast<int>(p));
      if (p.isReal()) value = std::to_string(static_cast<double>(p));
      t.parameters.emplace_back(p.name(), value);
    }
  }
  t.sample_sets = read_each(YamlReader::child(node, "sample_sets"), read_sample_set_use);
  t.train_positives = static_cast<std::size_t>(int_at(node, "train_positives"));
  t.train_negatives = static_cast<std::size_t>(int_at(node, "train_negatives"));
  t.stopped = text_at(node, "stopped");
  const FileNode v = YamlReader::child(node, "validation");
  if (v.isMap()) t.validation = read_validation_figures(v);
  return t;
}

// Nodes of a tree (format 2).
std::vector<LutNode> read_tree_nodes(const YamlReader& r, const FileNode& n, const std::string& context) {
  const FileNode nodes = r.need(n, "nodes", context);
  if (!nodes.isSeq()) r.bad("'" + context + "nodes' is not a list");
  std::vector<LutNode> out;
  int k = 0;
  for (auto it = nodes.begin(); it != nodes.end(); ++it, ++k) {
    const std::string where = context + "nodes[" + std::to_string(k) + "].";
    LutNode node;
    node.feature = r.integer(*it, "feature", where);
    const FileNode responses = r.need(*it, "responses", where);
    if (!responses.isSeq()) r.bad("'" + where + "responses' is not a list");
    responses >> node.responses;
    out.push_back(std::move(node));
  }
  return out;
}

ScoreCalibration read_calibration(const YamlReader& r, const FileNode& root) {
  const FileNode c = r.need(root, "calibration", "");
  ScoreCalibration out;
  out.method = r.text(c, "method", "calibration.");
  if (out.method != "platt" && out.method != "none") {
    r.bad("'calibration.method' is '" + out.method + "' (known: platt, none)");
  }
  out.a = r.real(c, "a", "calibration.");
  out.b = r.real(c, "b", "calibration.");
  if (!std::isfinite(out.a) || !std::isfinite(out.b) || out.a <= 0.0) {
    r.bad("'calibration' has a = " + std::to_string(out.a) + ", b = " + std::to_string(out.b) +
          " (a must be a positive finite number)");
  }
  out.positives = static_cast<std::size_t>(std::max(0, YamlReader::opt_int(c["positives"])));
  out.negatives = static_cast<std::size_t>(std::max(0, YamlReader::opt_int(c["negatives"])));
  out.source = YamlReader::opt_text(c["source"]);
  return out;
}

// operating_point (format 3, optional): P(person) strictly between 0 and 1.
std::optional<OperatingPoint> read_operating_point(const YamlReader& r, const FileNode& root) {
  const FileNode node = YamlReader::child(root, "operating_point");
  if (node.empty()) return std::nullopt;
  OperatingPoint point;
  point.probability = r.real(node, "probability", "operating_point.");
  if (!(point.probability > 0.0 && point.probability < 1.0)) {
    r.bad("'operating_point.probability' must lie strictly between 0 and 1");
  }
  point.rule = YamlReader::opt_text(node["rule"]);
  return point;
}

// detection_options (format 4, required there): a mapping of analyser option keys to texts, each a row of
// analyser_parameters() with a value the row accepts.
RecordedParameters read_detection_options(const YamlReader& r, const FileNode& root) {
  const FileNode node = r.need(root, "detection_options", "");
  if (!node.isMap() || node.size() == 0) r.bad("'detection_options' must be a mapping of options to values");
  RecordedParameters options;
  for (auto it = node.begin(); it != node.end(); ++it) {
    const std::string key = (*it).name();
    options.emplace_back(key, r.text(node, key, "detection_options."));
  }
  try {
    with_recorded_values(analyser_parameters(), options, AnalyserParams{});
  } catch (const Error& e) {
    r.bad("'detection_options': " + std::string(e.what()));
  }
  return options;
}

// training.crops (format 3, optional): how the training crops were cut.
CropProvenance read_crops_v3(const YamlReader& r, const FileNode& training) {
  CropProvenance crops;
  const FileNode node = YamlReader::child(training, "crops");
  if (node.empty()) return crops;
  crops.window_box = r.text(node, "window_box", "training.crops.");
  crops.window_scale = r.real(node, "window_scale", "training.crops.");
  if (!(crops.window_scale > 0.0) || !std::isfinite(crops.window_scale)) {
    r.bad("'training.crops.window_scale' must be a positive number");
  }
  return crops;
}

// Formats 1, 2 and 3 share their layout; 2 adds `calibration`, trees and validation.by_probability; 3
// adds training.crops.
BoostedModel read_v1_to_v4(const YamlReader& r, const FileNode& root, const FeatureSpec* expected, int format_version) {
  const FeatureSpec spec = read_feature_spec_v1(r, root, expected);
  const FileNode classifier = r.need(root, "classifier", "");
  const FileNode bins_node = r.need(classifier, "bins", "classifier.");
  const std::string scheme = r.text(bins_node, "scheme", "classifier.bins.");
  if (scheme != "uniform") r.bad("bin scheme '" + scheme + "' is not known (formats 1 to 3 have 'uniform')");
  BinScheme bins;
  bins.count = r.integer(bins_node, "count", "classifier.bins.");
  bins.min_value = r.single(bins_node, "min", "classifier.bins.");
  bins.max_value = r.single(bins_node, "max", "classifier.bins.");
  const FileNode weak_node = r.need(classifier, "weak_classifiers", "classifier.");
  if (!weak_node.isSeq()) r.bad("'classifier.weak_classifiers' is not a list");
  std::vector<WeakClassifier> weak;
  int index = 0;
  for (auto it = weak_node.begin(); it != weak_node.end(); ++it, ++index) {
    const FileNode n = *it;
    const std::string context = "classifier.weak_classifiers[" + std::to_string(index) + "].";
    WeakClassifier w;
    const std::string kind = r.text(n, "kind", context);
    w.feature = r.integer(n, "feature", context);
    if (kind == "lut") {
      w.kind = WeakClassifier::Kind::Lut;
      const FileNode responses = r.need(n, "responses", context);
      if (!responses.isSeq()) r.bad("'" + context + "responses' is not a list");
      responses >> w.responses;
    } else if (kind == "stump") {
      w.kind = WeakClassifier::Kind::Stump;
      w.threshold = r.real(n, "threshold", context);
      w.left = r.real(n, "left", context);
      w.right = r.real(n, "right", context);
    } else if (kind == "tree" && format_version >= 2) {
      w.kind = WeakClassifier::Kind::Tree;
      w.nodes = read_tree_nodes(r, n, context);
      if (w.nodes.empty() || w.nodes.front().feature != w.feature) {
        r.bad("'" + context + "feature' is not the feature of the tree's root");
      }
    } else {
      r.bad("'" + context + "kind' is '" + kind + "' (known: lut, stump" + (format_version >= 2 ? ", tree)" : ")"));
    }
    weak.push_back(std::move(w));
  }
  const FileNode count = classifier["weak_count"];
  if (count.isInt() && static_cast<int>(count) != index) {
    r.bad("weak_count says " + std::to_string(static_cast<int>(count)) + " but " + std::to_string(index) +
          " weak classifiers are listed (truncated file?)");
  }
  BoostedModel model;
  try {
    model = BoostedModel(spec, bins, std::move(weak));
  } catch (const Error& e) {
    r.bad(e.what());
  }
  model.set_identity(r.text(root, "name", ""), r.integer(root, "version", ""), r.path(), r.text(root, "created", ""));
  model.training() = read_training_v1(root["training"]);
  if (format_version >= 3) model.training().crops = read_crops_v3(r, root["training"]);
  model.set_format_version(format_version);
  if (format_version >= 2) model.set_calibration(read_calibration(r, root));
  if (format_version >= 3) model.set_operating_point(read_operating_point(r, root));
  if (format_version >= 4) model.set_detection_options(read_detection_options(r, root));
  const FileNode opencv = root["opencv_model"];
  if (opencv.isMap()) {
    FileStorage out(".yml", FileStorage::WRITE | FileStorage::MEMORY | FileStorage::FORMAT_YAML);
    copy_yaml_node(out, "opencv_model", opencv);
    model.set_opencv_model_yaml(out.releaseAndGetString());
  }
  return model;
}

// The file once OpenCV has parsed it.
BoostedModel read_opened(const YamlReader& r, const FileNode& root, const FeatureSpec* expected) {
  if (!root.isMap()) r.bad("not an rdsf model file (no 'format: " + std::string(kModelFormat) + "')");
  const FileNode format = root["format"];
  if (!format.isString() || static_cast<std::string>(format) != kModelFormat) {
    r.bad("not an rdsf model file (no 'format: " + std::string(kModelFormat) + "')");
  }
  const FileNode version = root["format_version"];
  if (!version.isInt()) r.bad("missing or non-integer 'format_version'");
  const int format_version = static_cast<int>(version);
  switch (format_version) {
    case 1:
    case 2:
    case 3:
    case 4:
      return read_v1_to_v4(r, root, expected, format_version);
    default:
      r.bad("model format version " + std::to_string(format_version) + " is not known (this build reads " +
            "versions 1 to 4; a newer rdsf wrote it?)");
  }
}

}  // namespace

std::string model_file_text(const BoostedModel& model) {
  FileStorage fs(".yml", FileStorage::WRITE | FileStorage::MEMORY | FileStorage::FORMAT_YAML);
  cv::write(fs, "format", std::string(kModelFormat));
  cv::write(fs, "format_version", model.detection_options().empty() ? kModelFormatVersion : kModelFormatVersionStated);
  cv::write(fs, "name", model.name());
  cv::write(fs, "version", model.version());
  cv::write(fs, "created", model.created());
  write_feature_spec(fs, model.feature_spec());
  write_training(fs, model.training());
  write_classifier(fs, model);
  write_calibration(fs, model.calibration());
  write_operating_point(fs, model.operating_point());
  write_detection_options(fs, model.detection_options());
  if (!model.opencv_model_yaml().empty()) {
    FileStorage embedded(model.opencv_model_yaml(), FileStorage::READ | FileStorage::MEMORY);
    copy_yaml_node(fs, "opencv_model", embedded["opencv_model"]);
  }
  return fs.releaseAndGetString();
}

namespace {

BoostedModel read_model_file_checked(const std::string& path, const FeatureSpec* expected) {
  const YamlReader r = YamlReader::from_file(path, "model file");
  return r.read([&](const YamlReader& reader) { return read_opened(reader, reader.root(), expected); });
}

}  // namespace

BoostedModel read_model_file(const std::string& path) { return read_model_file_checked(path, nullptr); }

BoostedModel read_model_file(const std::string& path, const FeatureSpec& expected) {
  return read_model_file_checked(path, &expected);
}

}  // namespace rdsf
