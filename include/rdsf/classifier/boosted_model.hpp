#pragma once
// A trained person classifier: H(x) = sum of weak responses over one RDSF vector (H > 0 means person), and
// P(person | x) = calibration.probability(H(x)): Platt scaling fitted on validation groups (format 2), or
// 1 / (1 + exp(-2 H)) for models without one (format 1 files: Real AdaBoost's half log-odds reading).
// Loaded from a model file (see model_file.hpp for the format, model_registry.hpp for NAME and NAME/vN).
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/classifier/bin_scheme.hpp"
#include "rdsf/classifier/operating_point.hpp"
#include "rdsf/classifier/platt_calibration.hpp"
#include "rdsf/classifier/training_record.hpp"
#include "rdsf/classifier/weak_classifier.hpp"
#include "rdsf/core/parameter_table.hpp"
#include "rdsf/features/feature_spec.hpp"

namespace rdsf {

class BoostedModel {
 public:
  BoostedModel() = default;
  BoostedModel(FeatureSpec spec, BinScheme bins, std::vector<WeakClassifier> weak);

  /// Loads a model file, or NAME (newest models/NAME/vN.yml under models_dir), or NAME/vN. Checks format
  /// version and feature spec hash (throws rdsf::Error saying which differs).
  static BoostedModel load(const std::string& path_or_name, const std::string& models_dir = "models");

  /// H(x) = sum of weak responses, one feature_spec().dimension()-value row.
  double score(const float* features) const { return score(features, weak_.size()); }
  /// The sum of the first `rounds` weak responses (all of them when rounds >= their count), added in the
  /// model's order from 0.0: bit for bit score() of a model of those weak classifiers alone.
  double score(const float* features, std::size_t rounds) const;
  /// One score per row (rows x dimension CV_32F); throws Error on a wrong column count.
  std::vector<double> score(const cv::Mat1f& rows) const;
  /// P(person) of a score H(x).
  double probability(double score) const { return calibration_.probability(score); }
  const ScoreCalibration& calibration() const { return calibration_; }
  void set_calibration(ScoreCalibration c) { calibration_ = std::move(c); }
  /// The operating point the model states (operating_point.hpp), if any.
  const std::optional<OperatingPoint>& operating_point() const { return operating_point_; }
  void set_operating_point(std::optional<OperatingPoint> point) { operating_point_ = std::move(point); }
  /// The P(person) a candidate needs to be a person when the user gives no threshold: the stated
  /// operating point, else kDefaultOperatingProbability (0.5).
  double operating_probability() const {
    return operating_point_ ? operating_point_->probability : kDefaultOperatingProbability;
  }
  /// The frame analyser's options the model states it was trained and measured with: (key, text) of every
  /// row of analyser_parameters() (segmentation, candidates), or none (empty: the detector's own options).
  /// A detector takes them for every option its user does not give (pipeline/stated_options.hpp); model
  /// files hold them from format 4 (model_file.hpp).
  const RecordedParameters& detection_options() const { return detection_options_; }
  void set_detection_options(RecordedParameters options) { detection_options_ = std::move(options); }
  /// Every feature index the weak classifiers read, ascending, without repeats.
  std::vector<int> used_features() const;

  const std::string& name() const { return name_; }  ///< "tree2"
  int version() const { return version_; }           ///< N of vN (0 before saving)
  const std::string& path() const { return path_; }  ///< file it came from (empty before saving)
  const FeatureSpec& feature_spec() const { return spec_; }

  // More than the shared contract: what the trainer and --inspect need.
  const BinScheme& bins() const { return bins_; }
  const std::vector<WeakClassifier>& weak_classifiers() const { return weak_; }
  /// The same model cut to its first `rounds` weak classifiers (early stopping, per-round figures).
  BoostedModel truncated(std::size_t rounds) const;
  const TrainingRecord& training() const { return training_; }
  TrainingRecord& training() { return training_; }
  const std::string& created() const { return created_; }  ///< ISO 8601 UTC, set when saved
  /// The OpenCV backend's cv::ml::Boost as FileStorage YAML text (empty for native models); kept in the
  /// model file for fidelity, while scoring uses the equivalent stumps.
  const std::string& opencv_model_yaml() const { return opencv_yaml_; }
  void set_opencv_model_yaml(std::string yaml) { opencv_yaml_ = std::move(yaml); }

  void set_identity(std::string name, int version, std::string path, std::string created);
  /// Format version of the file it was read from (the version written, for a model not read from a file).
  int format_version() const { return format_version_; }
  void set_format_version(int version) { format_version_ = version; }

 private:
  std::string name_;
  int version_ = 0;
  int format_version_ = 1;
  std::string path_;
  std::string created_;
  FeatureSpec spec_;
  BinScheme bins_;
  std::vector<WeakClassifier> weak_;
  TrainingRecord training_;
  std::string opencv_yaml_;
  ScoreCalibration calibration_;
  std::optional<OperatingPoint> operating_point_;
  RecordedParameters detection_options_;
};

}  // namespace rdsf
