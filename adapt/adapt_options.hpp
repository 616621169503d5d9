#pragma once
// rdsf-adapt's options (its own, the model's, the propagation's and the frame analyser's) and their checks, in one
// place: main parses, checks and runs.
#include <string>

#include "adapt/adapt_run.hpp"
#include "cli/cli.hpp"

namespace rdsf {

/// The options' text before it becomes AdaptOptions (check_options).
struct AdaptOptionText {
  std::string chart, chart_png;         ///< --chart, --chart-png: draw a benchmark's results instead
  std::string holdout_check = "auto";   ///< --holdout-check auto|on|off
  std::string switch_rule = "one";      ///< --switch-rule one|majority
  std::string base_cut = "defaults";    ///< --base-cut steps|stated|defaults
};

/// rdsf-adapt's options, in --help's order, writing into `o` and `text`.
cli::po::options_description adapt_options(const std::string& caption, AdaptOptions& o, AdaptOptionText& text);

/// After parsing: --holdout-check and --switch-rule into `o`, and every rule between options (cli::UsageError naming the option).
/// With --chart only --chart-png is needed.
void check_options(const AdaptOptionText& text, AdaptOptions& o);

}  // namespace rdsf
