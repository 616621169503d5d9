#pragma once
// Where models live: models/NAME/vN.yml, N = 1, 2, ... A new model gets N one higher than the newest; no
// version is ever overwritten (the file is written under a temporary name and hard-linked into place,
// which fails rather than replaces if another trainer took the same N meanwhile).
//
// Wherever a model is accepted, the user may give a file path, a model folder (models/tree2), NAME (its
// newest version under models_dir) or NAME/vN.
#include <string>

#include "rdsf/classifier/boosted_model.hpp"

namespace rdsf {

/// Throws Error unless `name` is 1-64 characters of letters, digits, '_', '-' and '.' (not starting with '.'),
/// and not "recipes" (the recipes' folder).
void validate_model_name(const std::string& name);

/// Highest N of models_dir/NAME/vN.yml, 0 when there is none.
int latest_model_version(const std::string& models_dir, const std::string& name);

/// The model file that `path_or_name` means (see above); throws Error naming what was looked for.
/// A NAME with no versions under models_dir, and a NAME/vN whose NAME has no folder there, are looked up in
/// the models shipped with the workbench too (shipped_models_dir(): the installed share/rdsf/models, or the
/// source tree's models/ for a build-tree program; it holds the default model people/v4.yml and the earlier
/// v1-v3). A NAME that has a folder under models_dir is never mixed with the shipped one of that name.
std::string resolve_model(const std::string& path_or_name, const std::string& models_dir = "models");

/// The name of the default model shipped in models/ (trained by scripts/train-default-model.sh).
inline constexpr const char* kDefaultModelName = "people";

/// The folder of the shipped models and recipes (core/shipped_data.hpp says where; empty when there is none).
std::string shipped_models_dir();

/// How a model is named, in two forms kept here so that every program writes them the same way; both are
/// the model file's path for a model without a name (not read from models/NAME/vN.yml):
///   model_reference: "NAME/vN", what --model accepts (the samples.tsv `model` column)
///   model_label:     "NAME vN", for people (progress lines, reports, --inspect)
std::string model_reference(const BoostedModel& model);
std::string model_label(const BoostedModel& model);

/// Saves `model` as models_dir/NAME/vN.yml with the next free N, setting its name, version, path and
/// creation time. Returns the path.
std::string save_new_model_version(BoostedModel& model, const std::string& name,
                                   const std::string& models_dir = "models");

}  // namespace rdsf
