#pragma once
// One declaration per parameter, after LightGBM's config.h (a parameter's name, alias, check and
// description written once, from which parsing and the docs are made), in C++ without a generator.
//
// A parameter struct (SegmentationParams, CandidateParams, BoostTrainingParams, ...) keeps its members and
// their defaults: that is the library's interface, and a default-constructed struct is the one statement
// of the defaults. Beside it, its table declares every other fact of each member once, in one row:
//   name    kebab-case: the command-line option (--near-height); with '_' for '-' the key of --config
//           files, recipes and provenance (near_height), which are also the thesis's names;
//   member  where the value lives (a member pointer, also through one nested struct);
//   help    the line --help prints (the default is printed beside it, from the struct);
//   check   an inclusive range [min, max] for numbers, or the words a text may be, or a function;
//   thesis  the value under --thesis when the row is a departure from the thesis;
//   classic (optional) the value under rdsf-synth's --classic (the generator before issue 13's variety);
//   hidden  (optional) no command-line option: a member only a preset sets (--classic's camera offset);
//   record  (optional) what provenance records of the row, when not simply (key, text): nothing for a row
//           that does not apply (a native-only option under another backend), or other text or pairs.
// The command line (cli::table_options), --config (the same options), recipes (read_parameters), the
// --thesis and --classic presets (with_preset_values), --help and so docs/options.md
// (scripts/option-reference.sh) and the programs' provenance are all made from the rows. A row's setter converts and checks: it throws
// Error("name must be ...") in one line, naming the row.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace rdsf {

/// A value as the tables carry it: bool, integers, real numbers or text.
using ParameterValue = std::variant<bool, int, std::int64_t, double, std::string>;

/// (key, text) pairs: what a model file or manifest records of parameters.
using RecordedParameters = std::vector<std::pair<std::string, std::string>>;

/// "1"/"0" for bool, the shortest round-trip text of a number ("%g" up to 17 digits: 0.3, 1500), text as is.
std::string parameter_text(const ParameterValue& value);

/// `name` with '-' as '_': the key of config files and recipes.
std::string parameter_key(const std::string& name);

/// Converts `value` to the type of `like` (an int where an int is expected, a number from an int, ...);
/// throws Error("name must be <type>") when it cannot.
ParameterValue convert_parameter(const ParameterValue& value, const ParameterValue& like, const std::string& name);

/// The first position at which two recorded lists differ (a key or a text, or one list ending first), or
/// none when they are the same.
std::optional<std::size_t> first_difference(const RecordedParameters& a, const RecordedParameters& b);

/// `text` in parameter_text's form read as a value of `like`'s type: "1" / "0" for bool, an integer, a finite
/// number (any strtod form), text as is; throws Error("name must be ...") when it is none.
ParameterValue parameter_value_of_text(const std::string& text, const ParameterValue& like, const std::string& name);

template <typename Params>
struct Parameter {
  std::string name;
  std::string help;
  std::function<ParameterValue(const Params&)> get;
  /// Converts to the row's type, checks, stores; throws Error("name must be ...").
  std::function<void(Params&, const ParameterValue&)> set;
  std::optional<ParameterValue> thesis;   ///< under --thesis, when a departure from the thesis
  std::optional<ParameterValue> classic;  ///< under rdsf-synth's --classic, when the variety changed it
  bool is_switch = false;                 ///< a flag on the command line (--relaxed; --relaxed=0 gives it off)
  bool hidden = false;                    ///< no command-line option: a member only a preset sets
  /// What provenance records of this row; empty: (parameter_key(name), parameter_text(get(params))).
  std::function<RecordedParameters(const Params&)> record;
};

template <typename Params>
using ParameterTable = std::vector<Parameter<Params>>;

/// An inclusive range of a number, or none.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  ///< min itself refused
  bool max_open = false;  ///< max itself refused
  static Range at_least(double min) { return {min, std::numeric_limits<double>::infinity(), false, false}; }
  static Range above(double min) { return {min, std::numeric_limits<double>::infinity(), true, false}; }
  static Range between(double min, double max) { return {min, max, false, false}; }  ///< [min, max]
  static Range from_below(double min, double max) { return {min, max, false, true}; }  ///< [min, max)
  static Range above_to(double min, double max) { return {min, max, true, false}; }    ///< (min, max]
  /// "" when `value` lies in the range, else "must be at least 0", "must be in [1, 4]", ...
  std::string problem(double value) const;
};

namespace parameter_detail {

template <typename T>
ParameterValue wrap(const T& v) {
  if constexpr (std::is_same_v<T, std::uint64_t>) {
    return static_cast<std::int64_t>(v);
  } else {
    return v;
  }
}

template <typename T>
T unwrap(const ParameterValue& v) {
  if constexpr (std::is_same_v<T, std::uint64_t>) {
    return static_cast<std::uint64_t>(std::get<std::int64_t>(v));
  } else {
    return std::get<T>(v);
  }
}

[[noreturn]] void refuse(const std::string& name, const std::string& problem);

}  // namespace parameter_detail

/// A row bound to `member` (bool, int, std::int64_t, std::uint64_t, double or std::string), checked by
/// `range` (numbers) and, when given, by `check` (returns the problem or ""), with `thesis` under --thesis.
template <typename Params, typename T>
Parameter<Params> parameter(std::string name, T Params::*member, std::string help, Range range = {},
                            std::optional<T> thesis = std::nullopt,
                            std::function<std::string(const T&)> check = {}) {
  Parameter<Params> row;
  row.name = name;
  row.help = std::move(help);
  row.get = [member](const Params& p) { return parameter_detail::wrap(p.*member); };
  const ParameterValue like = parameter_detail::wrap(T{});
  row.set = [member, name, range, like, check](Params& p, const ParameterValue& given) {
    const ParameterValue v = convert_parameter(given, like, name);
    const T value = parameter_detail::unwrap<T>(v);
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
      const std::string problem = range.problem(static_cast<double>(value));
      if (!problem.empty()) parameter_detail::refuse(name, problem);
    }
    if (check) {
      const std::string problem = check(value);
      if (!problem.empty()) parameter_detail::refuse(name, problem);
    }
    p.*member = value;
  };
  if (thesis) row.thesis = parameter_detail::wrap(*thesis);
  if constexpr (std::is_same_v<T, std::uint64_t>) {
    // A seed: never negative.
    row.set = [set = row.set, name](Params& p, const ParameterValue& given) {
      if (const auto* i = std::get_if<int>(&given); i != nullptr && *i < 0) parameter_detail::refuse(name, "must not be negative");
      if (const auto* i = std::get_if<std::int64_t>(&given); i != nullptr && *i < 0) {
        parameter_detail::refuse(name, "must not be negative");
      }
      set(p, given);
    };
  }
  return row;
}

/// A row whose value is computed (an enum shown as a word or a switch): `get` and `set` (which throws
/// Error through refuse_parameter() on a bad value).
template <typename Params, typename T>
Parameter<Params> computed_parameter(std::string name, std::string help, std::function<T(const Params&)> get,
                                     std::function<void(Params&, const T&)> set,
                                     std::optional<T> thesis = std::nullopt, bool is_switch = false) {
  Parameter<Params> row;
  row.name = name;
  row.help = std::move(help);
  row.get = [get](const Params& p) { return ParameterValue(get(p)); };
  const ParameterValue like = T{};
  row.set = [set, like, name](Params& p, const ParameterValue& given) {
    set(p, std::get<T>(convert_parameter(given, like, name)));
  };
  if (thesis) row.thesis = *thesis;
  row.is_switch = is_switch;
  return row;
}

/// Throws Error("name <problem>"): what a row's check says.
[[noreturn]] inline void refuse_parameter(const std::string& name, const std::string& problem) {
  parameter_detail::refuse(name, problem);
}

/// A row of the struct held as `member`, lifted into the struct that holds it.
template <typename Outer, typename Inner>
Parameter<Outer> nested(const Parameter<Inner>& row, Inner Outer::*member) {
  Parameter<Outer> lifted;
  lifted.name = row.name;
  lifted.help = row.help;
  lifted.thesis = row.thesis;
  lifted.classic = row.classic;
  lifted.is_switch = row.is_switch;
  lifted.hidden = row.hidden;
  if (row.record) lifted.record = [record = row.record, member](const Outer& o) { return record(o.*member); };
  lifted.get = [get = row.get, member](const Outer& o) { return get(o.*member); };
  lifted.set = [set = row.set, member](Outer& o, const ParameterValue& v) { set(o.*member, v); };
  return lifted;
}

/// The rows of `inner`'s table lifted into the struct that holds it as `member`.
template <typename Outer, typename Inner>
ParameterTable<Outer> nested(const ParameterTable<Inner>& inner, Inner Outer::*member) {
  ParameterTable<Outer> out;
  for (const Parameter<Inner>& row : inner) out.push_back(nested(row, member));
  return out;
}

/// parameter() bound to `member` of the struct held as `group` (a group of a struct's members, such as
/// CandidateParams::narrow): the row is the group's, lifted by nested().
template <typename Params, typename Group, typename T>
Parameter<Params> parameter(std::string name, Group Params::*group, T Group::*member, std::string help,
                            Range range = {}, std::optional<T> thesis = std::nullopt,
                            std::function<std::string(const T&)> check = {}) {
  return nested(parameter(std::move(name), member, std::move(help), range, std::move(thesis), std::move(check)),
                group);
}

/// `table`'s rows followed by `more`'s.
template <typename Params>
ParameterTable<Params> joined(ParameterTable<Params> table, const ParameterTable<Params>& more) {
  table.insert(table.end(), more.begin(), more.end());
  return table;
}

/// The row named `name`, or null.
template <typename Params>
const Parameter<Params>* find_parameter(const ParameterTable<Params>& table, const std::string& name) {
  for (const Parameter<Params>& row : table) {
    if (row.name == name) return &row;
  }
  return nullptr;
}

/// The rows of `table` from the one named `first` to the one named `last` (both included), in table order.
template <typename Params>
ParameterTable<Params> rows_between(const ParameterTable<Params>& table, const std::string& first,
                                    const std::string& last) {
  const auto begins = std::find_if(table.begin(), table.end(), [&](const Parameter<Params>& r) { return r.name == first; });
  const auto ends = std::find_if(begins, table.end(), [&](const Parameter<Params>& r) { return r.name == last; });
  return ParameterTable<Params>(begins, ends == table.end() ? ends : ends + 1);
}

/// A preset: the values of the rows' `thesis` or `classic` column (&Parameter<Params>::thesis, ...).
template <typename Params>
using Preset = std::optional<ParameterValue> Parameter<Params>::*;

/// `params` with every row's value under `preset` set (rows without one keep theirs).
template <typename Params>
Params with_preset_values(const ParameterTable<Params>& table, Preset<Params> preset, Params params) {
  for (const Parameter<Params>& row : table) {
    if (row.*preset) row.set(params, *(row.*preset));
  }
  return params;
}

/// `params` with every row's thesis value set.
template <typename Params>
Params with_thesis_values(const ParameterTable<Params>& table, Params params) {
  return with_preset_values(table, &Parameter<Params>::thesis, std::move(params));
}

/// What provenance records of `params`, in table order: each row's (key, text), or what its `record` gives.
template <typename Params>
RecordedParameters parameter_values(const ParameterTable<Params>& table, const Params& params) {
  RecordedParameters out;
  for (const Parameter<Params>& row : table) {
    if (row.record) {
      const RecordedParameters recorded = row.record(params);
      out.insert(out.end(), recorded.begin(), recorded.end());
    } else {
      out.emplace_back(parameter_key(row.name), parameter_text(row.get(params)));
    }
  }
  return out;
}

/// `params` with the value of each (key, text) of `values` set through `table`'s row of that key (text read
/// by parameter_value_of_text, checked by the row), except the keys in `skip`. Throws Error("'key' is not a
/// known option") for a key of no row, or the row's own Error("name must be ...").
template <typename Params>
Params with_recorded_values(const ParameterTable<Params>& table, const RecordedParameters& values, Params params,
                            const std::vector<std::string>& skip = {}) {
  for (const auto& [key, text] : values) {
    if (std::find(skip.begin(), skip.end(), key) != skip.end()) continue;
    const auto row = std::find_if(table.begin(), table.end(),
                                  [&key = key](const Parameter<Params>& r) { return parameter_key(r.name) == key; });
    if (row == table.end()) parameter_detail::refuse("'" + key + "'", "is not a known option");
    row->set(params, parameter_value_of_text(text, row->get(params), row->name));
  }
  return params;
}

/// `row` with its `record` set to `text`'s answer: no pair when it gives none, else (key, text).
template <typename Params>
Parameter<Params> recorded_as(Parameter<Params> row, std::function<std::optional<std::string>(const Params&)> text) {
  row.record = [key = parameter_key(row.name), text](const Params& p) {
    RecordedParameters out;
    if (const std::optional<std::string> t = text(p)) out.emplace_back(key, *t);
    return out;
  };
  return row;
}

}  // namespace rdsf
