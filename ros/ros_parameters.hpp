#pragma once
// The node's parameters from the ROS parameter server, read as its command-line options: every parameter
// in the node's private namespace (~NAME, e.g. /rdsf_people/threshold, or _threshold:=0.6 on rosrun's
// command line) becomes the option --NAME (snake_case names are aliases, as on every command line:
// ~row_step is --row-step), so one declaration (cli/cli.hpp's analyser and tracking options, the node's
// own in main.cpp) gives the parameter's name, type check, default and --help text.
//   bool    -> a switch (--relaxed) when true, nothing when false; "--name=true/false" for a bool value
//   int     -> --name=42;  double -> --name=0.6 (17 significant digits);  string -> --name=text
// A parameter that is not an option, or a list or dictionary, is a usage error naming it. An option given
// on the command line wins over the parameter of the same name (as over --config).
#include <string>
#include <vector>

#include "cli/cli.hpp"

namespace rdsf {

/// argv with the ROS parameters of the node's private namespace put in front as options (see above).
/// Call after ros::init (which takes the ROS remappings out of argv). With --help or --version in argv the
/// parameter server is not asked (no master needed). Throws cli::UsageError.
std::vector<std::string> arguments_with_parameters(int argc, char** argv,
                                                   const cli::po::options_description& options);

}  // namespace rdsf
