#include "adapt/adapt_state.hpp"

#include <filesystem>
#include <fstream>

#include "rdsf/core/atomic_file.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {

AdaptState::AdaptState(const std::string& out_dir)
    : path_((std::filesystem::path(out_dir) / "adapt-state.tsv").string()) {
  std::filesystem::create_directories(out_dir);
  std::ifstream in(path_);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    const std::size_t tab = line.find('\t');
    if (tab == std::string::npos || tab == 0) fail(path_, "line " + std::to_string(number) + ": not KEY<TAB>VALUE");
    values_[line.substr(0, tab)] = line.substr(tab + 1);
  }
}

std::string AdaptState::get(const std::string& key) const {
  const auto it = values_.find(key);
  return it == values_.end() ? std::string() : it->second;
}

void AdaptState::set(const std::string& key, const std::string& value) {
  values_[key] = value;
  AtomicTextFile file(path_, /*overwrite=*/true);
  for (const auto& [k, v] : values_) file.stream() << k << '\t' << v << '\n';
  file.commit();
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
