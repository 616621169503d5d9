#pragma once
// What a model file says about how its model was made: recipe, parameters, sample sets and the
// validation figures. Plain data; written and read by model_file. No timings: two trainings with the same
// inputs and seed give byte-identical model files apart from the creation time.
#include <cstddef>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "rdsf/candidates/crop_provenance.hpp"
#include "rdsf/classifier/roc_metrics.hpp"

namespace rdsf {

/// One sample set that fed the training.
struct SampleSetUse {
  std::string role;           ///< "pos", "neg", "validation-pos", "validation-neg", "matrix"
  std::string path;           ///< folder as given
  std::string manifest_hash;  ///< SampleSet::manifest_hash(), empty when not from a set
  std::size_t available = 0;  ///< samples of the wanted label in the set
  std::size_t used = 0;       ///< samples taken
};

/// Validation figures after one round (written every N rounds and after the last).
struct RoundFigures {
  int round = 0;
  int feature = 0;
  double train_error = 0.0;
  /// The model after this round on the validation set (all 0 when there is none); its error_rate is the
  /// model file's validation_error.
  RocSummary validation;
  std::vector<RocPoint> roc;  ///< validation ROC at the standard FAR levels (roc_at_far_levels)
};

/// Validation figures at a probability threshold: the samples with P(person) >= probability.
struct ProbabilityPoint {
  double probability = 0.0;
  double tar = 0.0;  ///< positives accepted / positives
  double far = 0.0;  ///< negatives accepted / negatives
};

struct ValidationFigures {
  std::string source;  ///< "held-out groups: 20% ...", "separate sets", or "none"
  std::size_t positives = 0, negatives = 0;
  RocSummary summary;            ///< of the final model
  std::vector<RocPoint> roc;     ///< final model, at standard FAR levels
  /// Final model with its calibration, at P(person) >= 0.05, 0.10, ..., 0.95 (format 2).
  std::vector<ProbabilityPoint> by_probability;
  std::vector<RoundFigures> rounds;
};

/// The parameter rdsf-adapt records in a model it trains for one room (the room's recording).
inline constexpr const char kAdaptedRoomParameter[] = "adapted_room";
/// The parameter of a model trained by continuing another (rdsf-train --init): that model's weak classifiers,
/// the first of this one's.
inline constexpr const char kInitWeakClassifiersParameter[] = "init_weak_classifiers";

struct TrainingRecord {
  std::string recipe;   ///< recipe name, or "ad hoc"
  std::string backend;  ///< "native" or "opencv"
  /// Every parameter as text, in a fixed order (rounds, bins, seed, ...).
  std::vector<std::pair<std::string, std::string>> parameters;
  /// True when `parameters` names kAdaptedRoomParameter: a model rdsf-adapt adapted to one room.
  bool adapted_to_a_room() const {
    for (const auto& [key, value] : parameters) {
      if (key == kAdaptedRoomParameter) return true;
    }
    return false;
  }
  /// The weak classifiers of the model it continued (parameter init_weak_classifiers, written by rdsf-train
  /// --init), 0 when it continued none or does not say.
  std::size_t inherited_weak_classifiers() const {
    for (const auto& [key, value] : parameters) {
      if (key == kInitWeakClassifiersParameter) return static_cast<std::size_t>(std::strtoull(value.c_str(), nullptr, 10));
    }
    return 0;
  }
  std::vector<SampleSetUse> sample_sets;
  /// How the training crops were cut (format 3; unknown in older files and for sets that do not record it).
  CropProvenance crops;
  std::size_t train_positives = 0, train_negatives = 0;
  std::string stopped;   ///< why training ended: "rounds", "early stopping at round N (best AUC)"
  ValidationFigures validation;
};

}  // namespace rdsf
