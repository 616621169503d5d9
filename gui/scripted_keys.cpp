#include "gui/scripted_keys.hpp"

#include <iostream>

#include "rdsf/core/error.hpp"

namespace rdsf::gui {

ScriptedKeys::ScriptedKeys(const std::string& path, std::function<char(const std::string&)> named,
                           std::function<char(char)> letter, std::string known)
    : path_(path), named_(std::move(named)), letter_(std::move(letter)), known_(std::move(known)) {
  if (path != "-") {
    file_.open(path);
    if (!file_) fail(path, "cannot be opened");
  }
}

std::istream& ScriptedKeys::in() { return path_ == "-" ? std::cin : file_; }

bool ScriptedKeys::next(char& key) {
  while (pending_.empty()) {
    std::string token;
    if (!(in() >> token)) return false;
    if (const char k = named_(token); k != '\0') {
      pending_.push_back(k);
      continue;
    }
    for (char c : token) {
      const char k = letter_(c);
      if (k == '\0') fail(path_ == "-" ? "standard input" : path_, "unknown key '" + std::string(1, c) + "' (keys: " + known_ + ")");
      pending_.push_back(k);
    }
  }
  key = pending_.front();
  pending_.erase(pending_.begin());
  return true;
}

}  // namespace rdsf::gui
