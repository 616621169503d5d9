#pragma once
// The candidate switches: analyser options that are off by default because each helps some rooms and costs
// others (docs/quality.md: measured with people/v3 on rendered and real rooms, none passes for every room),
// with the value that turns each on. rdsf-adapt tries them in a room (adapt/adapt_run.hpp, "switches"): a
// switch is taken when the person confirms a person among the candidates only it adds.
#include <string>
#include <vector>

namespace rdsf {

struct CandidateSwitch {
  std::string option;  ///< the analyser option's name (core/parameter_table.hpp), as on the command line
  std::string on;      ///< its value when on, as text (parameter_value_of_text)
  std::string finds;   ///< what it adds, for messages
};

/// In the order rdsf-adapt tries them.
inline const std::vector<CandidateSwitch>& candidate_switches() {
  static const std::vector<CandidateSwitch> all = {
      {"local-front", "70", "people standing against a wall or furniture, in its depth layer"},
      {"border-height", "25", "people the image's top or bottom edge cuts"},
      {"narrow-fitted-width", "20", "people whose passing columns are narrow (legs, poles, holes)"},
      {"hole-gap", "20", "people cut in two by missing readings"},
  };
  return all;
}

}  // namespace rdsf
