#include "rdsf/labeling/adapt_state_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "rdsf/core/error.hpp"

namespace rdsf {

AdaptStateValues parse_adapt_state(const std::string& text, const std::string& path) {
  AdaptStateValues values;
  std::size_t start = 0;
  for (int number = 1; start < text.size(); ++number) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    const std::size_t tab = line.find('\t');
    if (tab == std::string::npos || tab == 0) fail(path, "line " + std::to_string(number) + ": not KEY<TAB>VALUE");
    if (line.find('\r') != std::string::npos) fail(path, "line " + std::to_string(number) + ": a carriage return in it");
    values[line.substr(0, tab)] = line.substr(tab + 1);
  }
  return values;
}

AdaptStateValues read_adapt_state(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return {};
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a folder, not rdsf-adapt's state file");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) fail(path, "cannot be read");
  return parse_adapt_state(text.str(), path);
}

std::string adapt_state_text(const AdaptStateValues& values, const std::string& path) {
  std::string text;
  for (const auto& [key, value] : values) {
    if (key.empty() || key.find_first_of("\t\n\r") != std::string::npos) {
      fail(path, "key of " + std::to_string(key.size()) + " bytes is empty or holds a tab or line break");
    }
    if (value.find_first_of("\n\r") != std::string::npos) {
      fail(path, "the value of '" + key + "' holds a line break (state values are one line)");
    }
    text += key + '\t' + value + '\n';
  }
  return text;
}

}  // namespace rdsf
