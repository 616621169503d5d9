#pragma once
// What every program shares on the command line: option parsing with --help (every default shown) and
// --config FILE (INI; the command line wins), the frame analyser's options declared once, and the top-level
// error handling that turns any failure into one line and a non-zero exit.
#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <boost/program_options.hpp>

#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/parameter_table.hpp"
#include "rdsf/tracking/tracker.hpp"
#include "rdsf/frame/camera_model.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"
#include "rdsf/frame/frame_source.hpp"

namespace rdsf::cli {

namespace po = boost::program_options;

/// Thrown for a wrong command line; programs exit 2 on it (1 on every other error).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ProgramInfo {
  std::string name;     ///< "rdsf-detect"
  std::string usage;    ///< "--source SRC --out FILE.csv [options]"
  std::string summary;  ///< one paragraph shown by --help
};

/// The command-line convention (docs/options.md): option names are kebab-case with British spelling; the
/// thesis's snake_case names are aliases. Maps an option name as typed (without "--") to its canonical
/// name: '_' becomes '-', and the spelling aliases ("color") their British names. Used for argv and for
/// the keys of --config files.
std::string canonical_option_name(const std::string& name);

/// A default as --help shows it: "%g" (0.6, not 0.59999999999999998).
std::string shortest_text(double value);

/// Parses argv against `options` (plus --help, --version and --config), names made canonical first.
/// Returns false when --help or --version was printed (the program then exits 0). Throws UsageError on
/// unknown options, bad values or a bad config file.
bool parse(int argc, char** argv, const ProgramInfo& info, const po::options_description& options,
           po::variables_map& values, const po::positional_options_description* positional = nullptr);

/// The options of a parameter table's rows (core/parameter_table.hpp), bound to `params`: each row's name,
/// its help with the default `params` holds now, its type; a value the row's check refuses is a UsageError
/// ("--row-step must be at least 1"). Switch rows are flags (`--relaxed`), also given off as `--relaxed 0`.
template <typename Params>
void add_table_options(po::options_description& group, const ParameterTable<Params>& table, Params& params);

/// The options of add_table_options, but a value (given, from --config or the default) is not set: it is
/// appended to `values` as (row name, value), for the program to set through the rows later (rdsf-synth
/// sets them before its --classic preset; a refused value is its Error, exit 1). --help shows `params`' values.
template <typename Params>
void add_table_values(po::options_description& group, const ParameterTable<Params>& table, const Params& params,
                      std::vector<std::pair<std::string, ParameterValue>>& values);

/// The same rows as overrides: a row's value is appended to `given` only when given (command line or
/// --config); --help shows "Default X" from `defaults` (a recipe may set its own).
template <typename Params>
void add_override_options(po::options_description& group, const ParameterTable<Params>& table,
                          const Params& defaults, std::vector<std::pair<std::string, ParameterValue>>& given);

/// Sets `given` (from add_override_options) on `params` through `table`'s rows.
template <typename Params>
void apply_overrides(const ParameterTable<Params>& table, Params& params,
                     const std::vector<std::pair<std::string, ParameterValue>>& given);

/// Options of the frame analyser (segmentation, candidates: analyser_parameters()), bound to `params`, and
/// --feature-spec unless `feature_spec` is false (a program that keeps its model's features: rdsf-adapt).
po::options_description analyser_options(AnalyserParams& params, bool feature_spec = true);

/// After parse(), with analyser_options() among the options: the keys of the analyser options given (on the
/// command line, in --config, as a ROS parameter), and whether a model's stated detection options are taken
/// for the rest (pipeline/stated_options.hpp): not under --thesis.
GivenOptions given_analyser_options(const po::variables_map& values);

/// Analyser options as a program's arguments: {"--hole-gap", "20", ...}; a switch row is `--relaxed=1` or
/// `--relaxed=0` (given off, it wins over a model stating it on). For a program that runs others with its own
/// options (rdsf-adapt).
std::vector<std::string> analyser_arguments(const RecordedParameters& options);

/// --background DIR (a background model of the room, rdsf-background; off when not given) bound to `dir`, and
/// the foreground rule's margins (background_parameters()) bound to `params`.
po::options_description background_options(std::string& dir, BackgroundParams& params);
/// `analyser` with the background model of the folder `dir` (read_background; unchanged when `dir` is empty).
void apply_background(const std::string& dir, AnalyserParams& analyser);

/// --feature-spec NAME[:key=value,...] bound to `spec` (part of detector_options; rdsf-train adds it alone).
/// A name or parameter that is not known is a UsageError.
po::options_description feature_spec_options(FeatureSpec& spec);

/// --threshold, --score-threshold, --mirror-average and --suppress-duplicates (what makes a candidate a
/// person), added to `group` in that order and bound to `params` (rdsf-detect and the ROS node share them);
/// --thesis turns --mirror-average off unless it is given.
void add_decision_options(po::options_description& group, PipelineParams& params);

/// Options of the tracker (thesis names), bound to `params`.
po::options_description tracking_options(TrackingParams& params);

/// Parses a threshold list: "40,20,10,0" or "from:to:step" (e.g. "-60:40:5"); empty = the thesis's sweep.
std::vector<double> parse_thresholds(const std::string& text);

/// What a program's main does with the camera model's options, in one object: the constructor adds the
/// camera model's options (--fx, --fy, --cx, --cy: Kinect v1 defaults; the thesis's empirical calibration)
/// to `options`, and a bag's topics (--depth-topic, --colour-topic) after them when `frames` is given
/// (programs that read bags); apply() after parse() applies a given empirical calibration to `camera` and
/// then, with `frames`, completes them: the camera model and whether the user gave it (any of those options
/// not left at its default), so that it wins over a source's own model. It holds the calibration the
/// options are bound to, so it lives in main until apply() and is neither copied nor moved.
class CameraOptions {
 public:
  CameraOptions(po::options_description& options, CameraModel& camera, FrameSourceOptions* frames = nullptr);
  CameraOptions(const CameraOptions&) = delete;
  CameraOptions& operator=(const CameraOptions&) = delete;
  /// Call once after parse(); throws UsageError for an impossible calibration.
  void apply(const po::variables_map& values);

 private:
  CameraModel& camera_;
  FrameSourceOptions* frames_;
  EmpiricalCalibration calibration_;
};

/// parse(), then camera.apply(values): how a program that reads frames parses its command line.
bool parse(int argc, char** argv, const ProgramInfo& info, const po::options_description& options,
           po::variables_map& values, CameraOptions& camera);

/// Runs `body` and turns every failure into "NAME: error: ..." on stderr; returns the exit code
/// (0 success, 1 error, 2 usage error). An AlreadyExists error gets "(pass --force to replace it)".
int run(const std::string& program_name, const std::function<int()>& body);

// ---- templates ----

namespace detail {

/// A row's setter as a UsageError: "--name must be ..." instead of "name must be ...".
template <typename Params>
void set_as_option(const Parameter<Params>& row, Params& params, const ParameterValue& value) {
  try {
    row.set(params, value);
  } catch (const Error& e) {
    std::string message = e.what();
    const std::string named = row.name + " ";
    if (message.rfind(named, 0) == 0) message = message.substr(named.size());
    throw UsageError("--" + row.name + " " + message);
  }
}

/// Calls `make(T{})` with T the C++ type of `value`'s alternative.
template <typename Make>
auto with_type_of(const ParameterValue& value, Make&& make) {
  return std::visit([&](const auto& v) { return make(v); }, value);
}

}  // namespace detail

namespace detail {

/// The value of a switch row: `--relaxed` alone is on, `--relaxed 0` (or `=0`) off, so that an option a model
/// states on can be given off (pipeline/stated_options.hpp); 1, 0, on, off, true, false, yes, no.
inline po::typed_value<bool>* switch_value() { return po::value<bool>()->implicit_value(true, "1"); }

/// An option per row that is not hidden (a switch row a flag that may be given =0), its default `params`'
/// value; each value po::notify stores goes to `take(row, value)`.
template <typename Params, typename Take>
void add_row_options(po::options_description& group, const ParameterTable<Params>& table, const Params& params,
                     Take take) {
  for (const Parameter<Params>& row : table) {
    if (row.hidden) continue;
    if (row.is_switch) {
      const bool now = std::get<bool>(row.get(params));
      group.add_options()(row.name.c_str(),
                          switch_value()->default_value(now, now ? "1" : "0")->notifier([take, row](bool on) {
                            take(row, ParameterValue(on));
                          }),
                          row.help.c_str());
      continue;
    }
    with_type_of(row.get(params), [&](const auto& now) {
      using T = std::decay_t<decltype(now)>;
      group.add_options()(row.name.c_str(),
                          po::value<T>()->default_value(now, parameter_text(now))->notifier([take, row](const T& v) {
                            take(row, ParameterValue(v));
                          }),
                          row.help.c_str());
      return 0;
    });
  }
}

}  // namespace detail

template <typename Params>
void add_table_options(po::options_description& group, const ParameterTable<Params>& table, Params& params) {
  detail::add_row_options(group, table, params, [&params](const Parameter<Params>& row, const ParameterValue& v) {
    detail::set_as_option(row, params, v);
  });
}

template <typename Params>
void add_table_values(po::options_description& group, const ParameterTable<Params>& table, const Params& params,
                      std::vector<std::pair<std::string, ParameterValue>>& values) {
  detail::add_row_options(group, table, params, [&values](const Parameter<Params>& row, const ParameterValue& v) {
    values.emplace_back(row.name, v);
  });
}

template <typename Params>
void add_override_options(po::options_description& group, const ParameterTable<Params>& table,
                          const Params& defaults, std::vector<std::pair<std::string, ParameterValue>>& given) {
  for (const Parameter<Params>& row : table) {
    if (row.hidden) continue;
    const std::string help = row.help + ". Default " + (row.is_switch ? std::string("off") : parameter_text(row.get(defaults)));
    if (row.is_switch) {
      group.add_options()(row.name.c_str(), detail::switch_value()->notifier([&given, name = row.name](bool on) {
        given.emplace_back(name, on);
      }), help.c_str());
      continue;
    }
    detail::with_type_of(row.get(defaults), [&](const auto& like) {
      using T = std::decay_t<decltype(like)>;
      group.add_options()(row.name.c_str(), po::value<T>()->notifier([&given, name = row.name](const T& v) {
        given.emplace_back(name, v);
      }), help.c_str());
      return 0;
    });
  }
}

template <typename Params>
void apply_overrides(const ParameterTable<Params>& table, Params& params,
                     const std::vector<std::pair<std::string, ParameterValue>>& given) {
  for (const auto& [name, value] : given) {
    if (const Parameter<Params>* row = find_parameter(table, name)) detail::set_as_option(*row, params, value);
  }
}

}  // namespace rdsf::cli
