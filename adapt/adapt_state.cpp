#include "adapt/adapt_state.hpp"

#include <filesystem>

#include "rdsf/core/atomic_file.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/labeling/adapt_state_file.hpp"

namespace rdsf {

AdaptState::AdaptState(const std::string& out_dir)
    : path_((std::filesystem::path(out_dir) / "adapt-state.tsv").string()) {
  std::filesystem::create_directories(out_dir);
  values_ = read_adapt_state(path_);
}

std::string AdaptState::get(const std::string& key) const {
  const auto it = values_.find(key);
  return it == values_.end() ? std::string() : it->second;
}

void AdaptState::set(const std::string& key, const std::string& value) {
  std::map<std::string, std::string> values = values_;
  values[key] = value;
  const std::string text = adapt_state_text(values, path_);  // refuses what would not read back
  AtomicTextFile file(path_, /*overwrite=*/true);
  file.stream() << text;
  file.commit();
  values_ = std::move(values);
}

void AdaptState::pin(const std::string& key, const std::string& value) {
  const std::string before = get(key);
  if (before.empty()) {
    set(key, value);
  } else if (before != value) {
    fail(path_, "this folder adapts " + key + " '" + before + "', not '" + value + "': give another --out");
  }
}

}  // namespace rdsf
