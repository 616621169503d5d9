#include "rdsf/core/yaml_guard.hpp"

namespace rdsf {

std::string one_line(const std::string& text) {
  static const char* const hex = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if ((byte < 0x20 && c != '\t') || byte == 0x7f) {
      out += "\\x";
      out += hex[byte >> 4];
      out += hex[byte & 15];
    } else {
      out += c;
    }
  }
  return out;
}

std::string yaml_layout_problem(const std::string& text) {
  bool content = false;
  std::size_t line = 0;
  for (std::size_t start = 0; start < text.size();) {
    ++line;
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string row = text.substr(start, end - start);
    start = end + 1;
    const std::size_t first = row.find_first_not_of(" \t\r");
    if (first == std::string::npos || row[first] == '#') continue;  // blank or comment
    const std::string where = "line " + std::to_string(line) + ": ";
    const bool marker = row.compare(0, 3, "---") == 0 || row.compare(0, 3, "...") == 0;
    if (!content) {
      if (row[0] == '%') continue;  // directive
      if (row.compare(0, 3, "---") == 0) {
        if (row.find_first_not_of(" \t\r", 3) != std::string::npos) return where + "text after the '---' marker";
        continue;
      }
      if (first != 0) return where + "the top-level entries must start in the first column";
      content = true;
    } else if (marker && first == 0) {
      return where + "a second YAML document (only one is read)";
    }
  }
  return "";
}

}  // namespace rdsf
