#include "trainer/recipe.hpp"

#include <filesystem>

#include <opencv2/core.hpp>

#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {
namespace {

std::vector<std::string> string_list(const cv::FileNode& node, const std::string& path, const std::string& key) {
  std::vector<std::string> out;
  if (node.empty() || node.isNone()) return out;
  if (node.isString()) return {static_cast<std::string>(node)};
  if (!node.isSeq()) fail(path, "'" + key + "' must be a list of sample set folders");
  for (auto it = node.begin(); it != node.end(); ++it) {
    if (!(*it).isString()) fail(path, "'" + key + "' must hold folder names (text)");
    out.push_back(static_cast<std::string>(*it));
  }
  return out;
}

int integer(const cv::FileNode& root, const std::string& key, int fallback, const std::string& path) {
  const cv::FileNode node = root[key];
  if (node.empty() || node.isNone()) return fallback;
  if (!node.isInt()) fail(path, "'" + key + "' must be an integer");
  return static_cast<int>(node);
}

double real(const cv::FileNode& root, const std::string& key, double fallback, const std::string& path) {
  const cv::FileNode node = root[key];
  if (node.empty() || node.isNone()) return fallback;
  if (!node.isInt() && !node.isReal()) fail(path, "'" + key + "' must be a number");
  return static_cast<double>(node);
}

}  // namespace

Recipe load_recipe(const std::string& name_or_path, const std::string& models_dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::string path = name_or_path;
  if (!fs::is_regular_file(path, ec)) {
    path = (fs::path(models_dir) / "recipes" / (name_or_path + ".yml")).string();
    // The recipes shipped with the workbench (models/recipes, installed under share/rdsf/models/recipes).
    const fs::path shipped = fs::path(shipped_models_dir()) / "recipes" / (name_or_path + ".yml");
    if (!fs::is_regular_file(path, ec) && !shipped_models_dir().empty() && fs::is_regular_file(shipped, ec)) {
      path = shipped.string();
    }
    if (!fs::is_regular_file(path, ec)) {
      fail(name_or_path, "no such recipe (no file of that name, and no " + path + ")");
    }
  }
  cv::FileStorage fs_in;
  try {
    if (!fs_in.open(path, cv::FileStorage::READ | cv::FileStorage::FORMAT_YAML)) fail(path, "cannot be read");
  } catch (const cv::Exception& e) {
    fail(path, "is not a readable YAML recipe (" + std::string(e.err) + ")");
  }
  const cv::FileNode root = fs_in.root();
  Recipe r;
  r.path = path;
  const cv::FileNode name = root["recipe"];
  r.name = name.isString() ? static_cast<std::string>(name) : fs::path(path).stem().string();
  const cv::FileNode description = root["description"];
  if (description.isString()) r.description = static_cast<std::string>(description);
  const int positives = integer(root, "positives", 0, path), negatives = integer(root, "negatives", 0, path);
  if (positives < 0 || negatives < 0) fail(path, "'positives' and 'negatives' must not be negative");
  r.positives = static_cast<std::size_t>(positives);
  r.negatives = static_cast<std::size_t>(negatives);
  r.pos_sets = string_list(root["pos_sets"], path, "pos_sets");
  r.neg_sets = string_list(root["neg_sets"], path, "neg_sets");
  r.validation_pos_sets = string_list(root["validation_pos_sets"], path, "validation_pos_sets");
  r.validation_neg_sets = string_list(root["validation_neg_sets"], path, "validation_neg_sets");
  BoostTrainingParams& p = r.params;
  p.rounds = integer(root, "rounds", p.rounds, path);
  const cv::FileNode backend = root["backend"];
  if (backend.isString()) p.backend = static_cast<std::string>(backend);
  const int seed = integer(root, "seed", static_cast<int>(p.seed), path);
  if (seed < 0) fail(path, "'seed' must not be negative");
  p.seed = static_cast<std::uint64_t>(seed);
  p.bins.count = integer(root, "bins", p.bins.count, path);
  p.validation_fraction = real(root, "validation_fraction", p.validation_fraction, path);
  p.weight_trim = real(root, "weight_trim", p.weight_trim, path);
  p.early_stopping = integer(root, "early_stopping", p.early_stopping, path);
  p.report_every = integer(root, "report_every", p.report_every, path);
  p.depth = integer(root, "depth", p.depth, path);
  p.folds = integer(root, "folds", p.folds, path);
  p.learning_rate = real(root, "learning_rate", p.learning_rate, path);
  const cv::FileNode calibration = root["calibration"];
  if (calibration.isString()) p.calibration = static_cast<std::string>(calibration);
  try {
    validate_training_params(p);
  } catch (const Error& e) {
    fail(path, e.what());
  }
  return r;
}

}  // namespace rdsf
