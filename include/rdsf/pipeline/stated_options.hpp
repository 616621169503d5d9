#pragma once
// The detection options a model states (BoostedModel::detection_options, model file format 4): the frame
// analyser's options (segmentation, candidates) it was trained and measured with. A detector runs the model
// with them, except for the options its user gives:
//   value of option o = the user's, when o is given (command line, --config, a ROS parameter)
//                     = the model's stated value, else, unless the user asked for the thesis (--thesis)
//                     = the detector's default
// A candidate option that helps one model can cost another (docs/quality.md: new candidate kinds hurt
// models trained without them), so the options belong with the model that was measured with them. A
// model that states none (people/v1-v3, a lab's own models unless told) runs with the detector's own
// options; the default people/v4 states --local-front 70 (docs/quality.md, "people/v4").
#include <string>
#include <vector>

#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/core/parameter_table.hpp"

namespace rdsf {

/// What a model states of `params`: (key, text) of every row of analyser_parameters(), in table order.
RecordedParameters stated_options(const AnalyserParams& params);

/// The same of the defaults with `values` ((key, text) pairs) set: what --detection-options and the sample sets'
/// records make a model state. Throws Error naming an unknown key or a value its option refuses.
RecordedParameters stated_options(const RecordedParameters& values);

/// The analyser options a user gave, which a model's stated options never replace.
struct GivenOptions {
  /// The keys (parameter_key: "hole_gap") of the options given on the command line, in --config or as ROS
  /// parameters. Empty: a model's stated options replace every value (a library caller's default).
  std::vector<std::string> keys;
  /// false: no stated option is taken (--thesis asks for the thesis's behaviour, not the model's).
  bool take_stated = true;

  /// `params` as they run `model` (null: as they are): `model`'s stated options for every option whose key
  /// is not in `keys`, when take_stated.
  AnalyserParams for_model(AnalyserParams params, const BoostedModel* model) const;
  /// What the programs print of `model`'s stated options: "model room v1 states its detection options
  /// (--hole-gap 20): taken for the options not given" ("... not taken (--thesis)"); "" when it states none.
  std::string said_of(const BoostedModel& model) const;
};

/// The (key, text) of `stated` whose text differs from the detector's default, in their order.
RecordedParameters departures_from_defaults(const RecordedParameters& stated);

/// `options` as command-line words: "--hole-gap 20 --narrow-fitted-width 20" ("" for none); what the
/// programs print of a model's stated options.
std::string option_words(const RecordedParameters& options);

}  // namespace rdsf
