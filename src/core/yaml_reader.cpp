#include "rdsf/core/yaml_reader.hpp"

#include <cfloat>
#include <cmath>
#include <fstream>
#include <sstream>

namespace rdsf {
namespace {

bool absent(const cv::FileNode& node) { return node.empty() || node.isNone(); }

}  // namespace

YamlReader::YamlReader(const std::string& text, std::string path, std::string kind)
    : path_(std::move(path)), kind_(std::move(kind)) {
  if (const std::string problem = yaml_layout_problem(text); !problem.empty()) {
    bad(problem + " (not a " + kind_ + " this workbench wrote)");
  }
  try {
    if (!storage_.open(text, cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML)) {
      bad("is not a readable YAML " + kind_);
    }
  } catch (const Error&) {
    throw;
  } catch (const cv::Exception& e) {
    bad("is not a readable YAML " + kind_ + " (" + e.err + ")");
  } catch (const std::exception& e) {
    // OpenCV's parser lets standard exceptions through (std::length_error on some damaged files).
    bad("is not a readable YAML " + kind_ + " (" + e.what() + ")");
  }
}

YamlReader YamlReader::from_file(const std::string& path, const std::string& kind) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot be read (missing or no permission)");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return YamlReader(buffer.str(), path, kind);
}

void YamlReader::bad(const std::string& problem) const { fail(path_, one_line(problem)); }

cv::FileNode YamlReader::need(const cv::FileNode& parent, const std::string& key, const std::string& context) const {
  if (!parent.isMap()) {
    const std::string parent_name =
        context.empty() ? std::string("the file") : "'" + context.substr(0, context.size() - 1) + "'";
    bad("missing '" + context + key + "' (" + parent_name + " is not a mapping)");
  }
  const cv::FileNode node = parent[key];
  if (absent(node)) bad("missing '" + context + key + "'");
  return node;
}

std::string YamlReader::text(const cv::FileNode& parent, const std::string& key, const std::string& context) const {
  const cv::FileNode node = need(parent, key, context);
  if (!node.isString()) bad("'" + context + key + "' is not text");
  return static_cast<std::string>(node);
}

int YamlReader::integer(const cv::FileNode& parent, const std::string& key, const std::string& context) const {
  const cv::FileNode node = need(parent, key, context);
  if (!node.isInt()) bad("'" + context + key + "' is not an integer");
  return static_cast<int>(node);
}

double YamlReader::real(const cv::FileNode& parent, const std::string& key, const std::string& context) const {
  const cv::FileNode node = need(parent, key, context);
  if (!node.isInt() && !node.isReal()) bad("'" + context + key + "' is not a number");
  return static_cast<double>(node);
}

float YamlReader::single(const cv::FileNode& parent, const std::string& key, const std::string& context) const {
  const double value = real(parent, key, context);
  if (std::isfinite(value) && std::fabs(value) > FLT_MAX) bad("'" + context + key + "' is out of the float range");
  return static_cast<float>(value);
}

bool YamlReader::has(const cv::FileNode& parent, const std::string& key) const {
  return parent.isMap() && !absent(parent[key]);
}

std::string YamlReader::text_or(const cv::FileNode& parent, const std::string& key, std::string fallback,
                                const std::string& context) const {
  return has(parent, key) ? text(parent, key, context) : fallback;
}

int YamlReader::integer_or(const cv::FileNode& parent, const std::string& key, int fallback,
                           const std::string& context) const {
  return has(parent, key) ? integer(parent, key, context) : fallback;
}

double YamlReader::real_or(const cv::FileNode& parent, const std::string& key, double fallback,
                           const std::string& context) const {
  return has(parent, key) ? real(parent, key, context) : fallback;
}

std::vector<std::string> YamlReader::text_list(const cv::FileNode& parent, const std::string& key,
                                               const std::string& context) const {
  if (!has(parent, key)) return {};
  const cv::FileNode node = parent[key];
  if (node.isString()) return {static_cast<std::string>(node)};
  if (!node.isSeq()) bad("'" + context + key + "' is not a list");
  std::vector<std::string> out;
  for (auto it = node.begin(); it != node.end(); ++it) {
    if (!(*it).isString()) bad("'" + context + key + "' holds an entry that is not text");
    out.push_back(static_cast<std::string>(*it));
  }
  return out;
}

cv::FileNode YamlReader::child(const cv::FileNode& parent, const char* key) {
  return parent.isMap() ? parent[key] : cv::FileNode();
}
std::string YamlReader::opt_text(const cv::FileNode& n) { return n.isString() ? static_cast<std::string>(n) : ""; }
double YamlReader::opt_real(const cv::FileNode& n) { return (n.isInt() || n.isReal()) ? static_cast<double>(n) : 0.0; }
int YamlReader::opt_int(const cv::FileNode& n) { return n.isInt() ? static_cast<int>(n) : 0; }

}  // namespace rdsf
