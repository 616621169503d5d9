#pragma once
// A training recipe (models/recipes/NAME.yml): which sample sets, how many samples of each class, and the
// boosting parameters. The thesis's four: tree, tree2, hugeTree, treeLast. Sample set paths are relative
// to the current folder (run rdsf-train from the project root) unless absolute.
//
//   recipe: tree2
//   description: "..."
//   positives: 4028          # 0 = every positive of the sets
//   negatives: 7484
//   pos_sets: [ "datasets/people" ]
//   neg_sets: [ "datasets/negatives" ]
//   validation_pos_sets: [ ]  # optional: a separate validation set instead of a held-out fraction
//   validation_neg_sets: [ ]
//   rounds: 100
//   backend: native          # or opencv
//   seed: 1
//   bins: 64
//   validation_fraction: 0.2
//   weight_trim: 0
//   early_stopping: 0
#include <string>
#include <vector>

#include "rdsf/classifier/boost_training.hpp"

namespace rdsf {

struct Recipe {
  std::string name;
  std::string description;
  std::string path;  ///< file it came from
  std::size_t positives = 0, negatives = 0;  ///< 0 = all
  std::vector<std::string> pos_sets, neg_sets, validation_pos_sets, validation_neg_sets;
  BoostTrainingParams params;
};

/// Reads models_dir/recipes/NAME.yml, or the file `name_or_path` when it exists, or else the shipped
/// recipe shipped_models_dir()/recipes/NAME.yml. Throws Error naming the file and the bad field.
Recipe load_recipe(const std::string& name_or_path, const std::string& models_dir);

/// The recipe in `text`, read from `path` (named in errors): every entry but the sets is optional (the
/// defaults of BoostTrainingParams); a damaged layout is refused before OpenCV reads it (yaml_reader.hpp).
Recipe parse_recipe(const std::string& text, const std::string& path);

}  // namespace rdsf
