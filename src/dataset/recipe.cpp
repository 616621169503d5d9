#include "rdsf/dataset/recipe.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <opencv2/core.hpp>

#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/yaml_reader.hpp"

namespace rdsf {

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
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be read (missing or no permission)");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_recipe(buffer.str(), path);
}

Recipe parse_recipe(const std::string& text, const std::string& path) {
  const YamlReader reader(text, path, "recipe");
  return reader.read([](const YamlReader& y) {
    const cv::FileNode root = y.root();
    if (!root.isMap()) y.bad("is not a recipe (no mapping of entries at the top level)");
    Recipe r;
    r.path = y.path();
    r.name = y.text_or(root, "recipe", std::filesystem::path(y.path()).stem().string());
    r.description = y.text_or(root, "description", "");
    const int positives = y.integer_or(root, "positives", 0), negatives = y.integer_or(root, "negatives", 0);
    if (positives < 0 || negatives < 0) y.bad("'positives' and 'negatives' must not be negative");
    r.positives = static_cast<std::size_t>(positives);
    r.negatives = static_cast<std::size_t>(negatives);
    r.pos_sets = y.text_list(root, "pos_sets");
    r.neg_sets = y.text_list(root, "neg_sets");
    r.validation_pos_sets = y.text_list(root, "validation_pos_sets");
    r.validation_neg_sets = y.text_list(root, "validation_neg_sets");
    BoostTrainingParams& p = r.params;
    p.rounds = y.integer_or(root, "rounds", p.rounds);
    p.backend = y.text_or(root, "backend", p.backend.name());
    const int seed = y.integer_or(root, "seed", static_cast<int>(p.seed));
    if (seed < 0) y.bad("'seed' must not be negative");
    p.seed = static_cast<std::uint64_t>(seed);
    p.bins.count = y.integer_or(root, "bins", p.bins.count);
    p.validation_fraction = y.real_or(root, "validation_fraction", p.validation_fraction);
    p.weight_trim = y.real_or(root, "weight_trim", p.weight_trim);
    p.early_stopping = y.integer_or(root, "early_stopping", p.early_stopping);
    p.report_every = y.integer_or(root, "report_every", p.report_every);
    p.depth = y.integer_or(root, "depth", p.depth);
    p.folds = y.integer_or(root, "folds", p.folds);
    p.learning_rate = y.real_or(root, "learning_rate", p.learning_rate);
    p.calibration = y.text_or(root, "calibration", p.calibration);
    try {
      validate_training_params(p);
    } catch (const Error& e) {
      y.bad(e.what());
    }
    return r;
  });
}

}  // namespace rdsf
