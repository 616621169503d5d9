#include "rdsf/core/parameter_table.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "rdsf/core/error.hpp"

namespace rdsf {

std::string parameter_text(const ParameterValue& value) {
  if (const auto* b = std::get_if<bool>(&value)) return *b ? "1" : "0";
  if (const auto* i = std::get_if<int>(&value)) return std::to_string(*i);
  if (const auto* l = std::get_if<std::int64_t>(&value)) return std::to_string(*l);
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  const double d = std::get<double>(value);
  char text[40];
  for (int precision = 6; precision <= 17; ++precision) {  // "%g", with more digits only when needed
    std::snprintf(text, sizeof text, "%.*g", precision, d);
    if (std::strtod(text, nullptr) == d) break;
  }
  return text;
}

std::string parameter_key(const std::string& name) {
  std::string key = name;
  std::replace(key.begin(), key.end(), '-', '_');
  return key;
}

std::optional<std::size_t> first_difference(const RecordedParameters& a, const RecordedParameters& b) {
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
    if (a[i] != b[i]) return i;
  }
  if (a.size() != b.size()) return std::min(a.size(), b.size());
  return std::nullopt;
}

ParameterValue parameter_value_of_text(const std::string& text, const ParameterValue& like, const std::string& name) {
  if (std::holds_alternative<std::string>(like)) return text;
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  if (std::holds_alternative<double>(like)) {
    const double d = std::strtod(begin, &end);
    if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(d)) {
      parameter_detail::refuse(name, "must be a number, not '" + text + "'");
    }
    return d;
  }
  const long long whole = std::strtoll(begin, &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE) parameter_detail::refuse(name, "must be an integer, not '" + text + "'");
  return convert_parameter(static_cast<std::int64_t>(whole), like, name);
}

namespace parameter_detail {

void refuse(const std::string& name, const std::string& problem) { throw Error(name + " " + problem); }

}  // namespace parameter_detail

ParameterValue convert_parameter(const ParameterValue& value, const ParameterValue& like, const std::string& name) {
  if (value.index() == like.index()) return value;
  const auto* i = std::get_if<int>(&value);
  const auto* l = std::get_if<std::int64_t>(&value);
  const std::optional<std::int64_t> whole = i ? std::optional<std::int64_t>(*i) : l ? std::optional(*l) : std::nullopt;
  if (std::holds_alternative<bool>(like)) {
    if (whole && (*whole == 0 || *whole == 1)) return *whole == 1;
    parameter_detail::refuse(name, "must be 0 or 1");
  }
  if (std::holds_alternative<int>(like)) {
    if (whole && *whole >= std::numeric_limits<int>::min() && *whole <= std::numeric_limits<int>::max()) {
      return static_cast<int>(*whole);
    }
    parameter_detail::refuse(name, "must be an integer");
  }
  if (std::holds_alternative<std::int64_t>(like)) {
    if (whole) return *whole;
    parameter_detail::refuse(name, "must be an integer");
  }
  if (std::holds_alternative<double>(like)) {
    if (whole) return static_cast<double>(*whole);
    parameter_detail::refuse(name, "must be a number");
  }
  parameter_detail::refuse(name, "must be text");
}

std::string Range::problem(double value) const {
  const bool inside = (min_open ? value > min : value >= min) && (max_open ? value < max : value <= max);  // NaN: never
  if (inside) return "";
  if (std::isinf(max)) return (min_open ? "must be above " : "must be at least ") + parameter_text(min);
  if (std::isinf(min)) return (max_open ? "must be below " : "must be at most ") + parameter_text(max);
  return "must be in " + std::string(min_open ? "(" : "[") + parameter_text(min) + ", " + parameter_text(max) +
         (max_open ? ")" : "]");
}

}  // namespace rdsf
