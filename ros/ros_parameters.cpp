#include "ros/ros_parameters.hpp"

#include <cstdio>
#include <set>

#include <ros/names.h>
#include <ros/param.h>
#include <ros/this_node.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include "rdsf/core/error.hpp"

namespace rdsf {
namespace {

bool asks_for_help(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string token = argv[i];
    if (token == "--help" || token == "-h" || token == "--version") return true;
  }
  return false;
}

// The canonical names of the options given on the command line ("--name" and "--name=value").
std::set<std::string> command_line_options(int argc, char** argv) {
  std::set<std::string> names;
  for (int i = 1; i < argc; ++i) {
    const std::string token = argv[i];
    if (token == "--") break;
    if (token.size() > 2 && token.compare(0, 2, "--") == 0) {
      names.insert(cli::canonical_option_name(token.substr(2, token.find('=') - 2)));
    }
  }
  return names;
}

// The option token of one parameter (empty for a switch that is false).
std::string option_token(const std::string& parameter, const std::string& option, XmlRpc::XmlRpcValue& value,
                         const cli::po::option_description& declared) {
  const bool is_switch = declared.semantic()->max_tokens() == 0;
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      if (is_switch) return static_cast<bool>(value) ? "--" + option : "";
      return "--" + option + (static_cast<bool>(value) ? "=true" : "=false");
    case XmlRpc::XmlRpcValue::TypeInt:
      if (!is_switch) return "--" + option + "=" + std::to_string(static_cast<int>(value));
      break;
    case XmlRpc::XmlRpcValue::TypeDouble:
      if (!is_switch) {
        char text[40];
        std::snprintf(text, sizeof text, "%.17g", static_cast<double>(value));
        return "--" + option + "=" + text;
      }
      break;
    case XmlRpc::XmlRpcValue::TypeString:
      if (!is_switch) return "--" + option + "=" + static_cast<std::string>(value);
      break;
    default:
      throw cli::UsageError("ROS parameter " + parameter + ": a list or dictionary is not a value of --" + option);
  }
  throw cli::UsageError("ROS parameter " + parameter + ": --" + option + " is a switch: give true or false");
}

}  // namespace

std::vector<std::string> arguments_with_parameters(int argc, char** argv,
                                                   const cli::po::options_description& options) {
  std::vector<std::string> arguments{argc > 0 ? argv[0] : "rdsf_people"};
  if (!asks_for_help(argc, argv)) {
    const std::set<std::string> given = command_line_options(argc, argv);
    const std::string prefix = ros::names::resolve("~") + "/";
    std::vector<std::string> names;
    if (!ros::param::getParamNames(names)) throw Error("cannot list the ROS parameters (is the master running?)");
    for (const std::string& name : names) {
      if (name.compare(0, prefix.size(), prefix) != 0) continue;
      const std::string option = cli::canonical_option_name(name.substr(prefix.size()));
      const cli::po::option_description* declared = options.find_nothrow(option, false);
      if (declared == nullptr) {
        throw cli::UsageError("ROS parameter " + name + " is not a parameter of " + ros::this_node::getName() +
                              " (its parameters are the options of rdsf_people --help)");
      }
      if (given.count(option) != 0) continue;  // the command line wins
      XmlRpc::XmlRpcValue value;
      if (!ros::param::get(name, value)) continue;  // deleted meanwhile
      const std::string token = option_token(name, option, value, *declared);
      if (!token.empty()) arguments.push_back(token);
    }
  }
  for (int i = 1; i < argc; ++i) arguments.emplace_back(argv[i]);
  return arguments;
}

}  // namespace rdsf
