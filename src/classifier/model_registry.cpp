#include "rdsf/classifier/model_registry.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "rdsf/classifier/model_file.hpp"
#include "rdsf/core/durable_io.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/shipped_data.hpp"
#include "rdsf/core/utc_time.hpp"

namespace rdsf {
namespace fs = std::filesystem;
namespace {

// N of "vN.yml", or 0.
int version_of_file_name(const std::string& file_name) {
  static const std::regex pattern("v([1-9][0-9]{0,8})\\.yml");
  std::smatch match;
  return std::regex_match(file_name, match, pattern) ? std::stoi(match[1].str()) : 0;
}

int latest_in_folder(const fs::path& folder) {
  int latest = 0;
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return 0;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if (entry.is_regular_file(ec)) latest = std::max(latest, version_of_file_name(entry.path().filename().string()));
  }
  return latest;
}

}  // namespace

void validate_model_name(const std::string& name) {
  static const std::regex pattern("[A-Za-z0-9_-][A-Za-z0-9_.-]{0,63}");
  if (!std::regex_match(name, pattern)) {
    throw Error("model name '" + name + "': use 1-64 letters, digits, '_', '-' or '.' (not starting with '.')");
  }
  if (name == "recipes") throw Error("model name 'recipes' is reserved (models/recipes holds the training recipes)");
}

int latest_model_version(const std::string& models_dir, const std::string& name) {
  return latest_in_folder(fs::path(models_dir) / name);
}

std::string shipped_models_dir() { return shipped_data_models_dir(); }

std::string resolve_model(const std::string& path_or_name, const std::string& models_dir) {
  std::error_code ec;
  const fs::path given(path_or_name);
  if (fs::is_regular_file(given, ec)) return path_or_name;
  if (fs::is_directory(given, ec)) {
    const int latest = latest_in_folder(given);
    if (latest == 0) fail(path_or_name, "folder holds no model versions (v1.yml, v2.yml, ...)");
    return (given / ("v" + std::to_string(latest) + ".yml")).string();
  }
  static const std::regex name_version("([A-Za-z0-9_][A-Za-z0-9_.-]*)/v([1-9][0-9]{0,8})(\\.yml)?");
  std::smatch match;
  if (std::regex_match(path_or_name, match, name_version)) {
    const fs::path version = fs::path(match[1].str()) / ("v" + match[2].str() + ".yml");
    const fs::path file = fs::path(models_dir) / version;
    if (fs::is_regular_file(file, ec)) return file.string();
    // NAME/vN of the shipped models (people/v1) wherever the program runs, as NAME alone is.
    if (!shipped_models_dir().empty() && !fs::is_directory(fs::path(models_dir) / match[1].str(), ec)) {
      const fs::path shipped = fs::path(shipped_models_dir()) / version;
      if (fs::is_regular_file(shipped, ec)) return shipped.string();
      fail(path_or_name, "no such model version (looked for " + file.string() + " and " + shipped.string() + ")");
    }
    fail(path_or_name, "no such model version (looked for " + file.string() + ")");
  }
  static const std::regex plain_name("[A-Za-z0-9_][A-Za-z0-9_.-]*");
  if (std::regex_match(path_or_name, plain_name)) {
    fs::path folder = fs::path(models_dir) / path_or_name;
    int latest = latest_in_folder(folder);
    // The models shipped with the workbench (models/people: the default model) wherever the program runs.
    const fs::path shipped = fs::path(shipped_models_dir()) / path_or_name;
    if (latest == 0 && !shipped_models_dir().empty() && latest_in_folder(shipped) > 0) {
      folder = shipped;
      latest = latest_in_folder(folder);
    }
    if (latest == 0) {
      fail(path_or_name, "no such model file, and no model versions under " + folder.string() + "/");
    }
    return (folder / ("v" + std::to_string(latest) + ".yml")).string();
  }
  fail(path_or_name, "no such model file");
}

std::string save_new_model_version(BoostedModel& model, const std::string& name, const std::string& models_dir) {
  validate_model_name(name);
  const fs::path folder = fs::path(models_dir) / name;
  create_folders_durably(folder.string());  // core/durable_io: synced into its parent
  const std::string created = utc_now_iso8601();
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int version = latest_in_folder(folder) + 1;
    const fs::path final_path = folder / ("v" + std::to_string(version) + ".yml");
    const fs::path partial = folder / (".v" + std::to_string(version) + ".yml." + std::to_string(::getpid()) + ".partial");
    model.set_identity(name, version, final_path.string(), created);
    // Data on disk before the name (core/durable_io): a power cut never leaves an empty vN.yml.
    write_synced(partial.string(), model_file_text(model));
    bool linked = false;
    try {
      linked = link_durably(partial.string(), final_path.string());  // never replaces a taken name
    } catch (...) {
      io::unlink(partial.string());
      throw;
    }
    io::unlink(partial.string());  // best effort: the model is in place already
    if (linked) return final_path.string();
  }
  fail(folder.string(), "could not find a free version number");
}

std::string model_reference(const BoostedModel& model) {
  return model.name().empty() ? model.path() : model.name() + "/v" + std::to_string(model.version());
}

std::string model_label(const BoostedModel& model) {
  return model.name().empty() ? model.path() : model.name() + " v" + std::to_string(model.version());
}

}  // namespace rdsf
