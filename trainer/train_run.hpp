#pragma once
// rdsf-train's pieces: train a model from a recipe or from sets given on the command line, inspect a model
// file, export the chosen samples in the thesis's text format.
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "rdsf/classifier/boost_training.hpp"
#include "rdsf/classifier/row_shards.hpp"
#include "trainer/training_data_parameters.hpp"

namespace rdsf {

struct TrainOptions {
  std::string recipe;  ///< name (models_dir/recipes/NAME.yml) or file
  std::vector<std::string> pos_sets, neg_sets, validation_pos_sets, validation_neg_sets;
  std::optional<std::size_t> positives, negatives;  ///< override the recipe; 0 = all
  std::string name;  ///< model name; default the recipe's name
  std::string models_dir = "models";
  /// Boosting parameters given on the command line (rows of boost_training_parameters(), in the order
  /// given): they override the recipe's (or the defaults').
  std::vector<std::pair<std::string, ParameterValue>> boosting;
  /// Rows of training_data_parameters() given on the command line, in the order given: they override the
  /// defaults (and the thesis's values under --thesis).
  std::vector<std::pair<std::string, ParameterValue>> training_data;
  bool thesis = false;             ///< the thesis's weak learners: depth 1, learning rate 1, no augmentation
  int threads = 0;
  FeatureSpec feature_spec;          ///< --feature-spec (checked against the sets only when given)
  bool feature_spec_given = false;
  std::size_t feature_pool = 0;      ///< see SampleChoice::feature_pool
  std::size_t memory_budget_mb = 4096;
  /// Continued training: start from this model (path, NAME or NAME/vN; the shipped `people` too): the new
  /// rounds follow its weak classifiers, on the given sets; the new model keeps both. Empty: from nothing.
  std::string init;
  /// Extra provenance recorded with the training parameters, "key=value" each (rdsf-adapt: room, answers, base).
  std::vector<std::string> provenance;
  /// The detection options the model states (NAME=VALUE each, NAME an analyser option such as hole-gap;
  /// "defaults" alone: this build's defaults): every analyser option at its default but those given.
  /// Empty: the options every sample set records alike, else the --init model's, else none
  /// (pipeline/stated_options.hpp).
  std::vector<std::string> detection_options;
  std::string inspect;      ///< model to describe instead of training
  int top = 20;             ///< --inspect: features listed
  std::string export_text;  ///< write the chosen samples here instead of training
  bool force = false;       ///< --export-text may replace a file
};

/// The validation groups and augmentation of a run: the defaults, the thesis's values under --thesis, then
/// the options given (cli::UsageError when one is refused).
TrainingDataParams effective_training_data(const TrainOptions& options);

/// Checks the command line's choice of job (cli::UsageError, exit 2): --inspect or --export-text, not both,
/// neither under mpirun (`ranks`); training and --export-text need --recipe or --pos and --neg. The checks
/// that need the recipe file (and the other ranks) follow in run_train and run_export_text. Call once, first.
void check_options(const TrainOptions& options, bool ranks);

/// Trains and saves models_dir/NAME/vN.yml; progress on stderr. Returns the exit code.
int run_train(const TrainOptions& options);

/// The same over the ranks of `shards` (mpirun -np N rdsf-train, docs/scaling.md): every rank checks that
/// the others have its options, feature spec and sample sets, computes the feature rows of its share only,
/// and trains with the others; rank 0 reports progress and writes the model, the others write nothing.
int run_train(const TrainOptions& options, const RowShards& shards);

/// Prints the header, figures and most used features of a model file (or NAME, NAME/vN) to `out`.
int run_inspect(const TrainOptions& options, std::ostream& out);

/// Writes the samples a training run would use in the thesis's text format.
int run_export_text(const TrainOptions& options);

}  // namespace rdsf
