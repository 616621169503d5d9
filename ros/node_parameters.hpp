#pragma once
// rdsf_people's own parameters (core/parameter_table.hpp): colour, its pairing and the diagnostics period,
// each declared once with its help and check; the node's options (and so its ~NAME parameters, --help and
// docs/options.md) are made from the rows. The model, thread, analyser and tracking options come from cli.
#include "rdsf/core/parameter_table.hpp"
#include "ros/people_node_run.hpp"

namespace rdsf {

const ParameterTable<PeopleNodeOptions>& node_parameters();

}  // namespace rdsf
