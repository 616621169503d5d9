#include "rdsf/pipeline/stated_options.hpp"

#include <algorithm>

#include "rdsf/classifier/model_registry.hpp"

namespace rdsf {

RecordedParameters stated_options(const AnalyserParams& params) {
  RecordedParameters out;
  for (const Parameter<AnalyserParams>& row : analyser_parameters()) {
    out.emplace_back(parameter_key(row.name), parameter_text(row.get(params)));
  }
  return out;
}

RecordedParameters stated_options(const RecordedParameters& values) {
  return stated_options(with_recorded_values(analyser_parameters(), values, AnalyserParams{}));
}

AnalyserParams GivenOptions::for_model(AnalyserParams params, const BoostedModel* model) const {
  if (model == nullptr || !take_stated) return params;
  return with_recorded_values(analyser_parameters(), model->detection_options(), std::move(params), keys);
}

std::string GivenOptions::said_of(const BoostedModel& model) const {
  if (model.detection_options().empty()) return "";
  const std::string departures = option_words(departures_from_defaults(model.detection_options()));
  return "model " + model_label(model) + " states its detection options (" +
         (departures.empty() ? std::string("the defaults") : departures) +
         (take_stated ? "): taken for the options not given" : "): not taken (--thesis)");
}

RecordedParameters departures_from_defaults(const RecordedParameters& stated) {
  const RecordedParameters defaults = stated_options(AnalyserParams{});
  RecordedParameters out;
  for (const auto& option : stated) {
    const auto same = std::find(defaults.begin(), defaults.end(), option);
    if (same == defaults.end()) out.push_back(option);
  }
  return out;
}

std::string option_words(const RecordedParameters& options) {
  std::string out;
  for (const auto& [key, text] : options) {
    std::string name = key;
    std::replace(name.begin(), name.end(), '_', '-');
    out += (out.empty() ? "--" : " --") + name + " " + text;
  }
  return out;
}

}  // namespace rdsf
