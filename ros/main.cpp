// rdsf_people: the ROS 1 node. Subscribes to a depth image with its camera_info (and optionally a colour
// image registered to it), finds and tracks people with rdsf::PeopleDetector in live mode, and publishes
// them (docs/ros.md). Its parameters (~NAME) are the options below (ros/ros_parameters.hpp).
#include <ros/init.h>

#include "cli/cli.hpp"
#include "cli/common_options.hpp"
#include "ros/node_parameters.hpp"
#include "ros/people_node_run.hpp"
#include "ros/ros_parameters.hpp"

const rdsf::cli::ProgramInfo kProgram{
    "rdsf_people", "[ROS remappings] [--NAME VALUE ...]   (rosrun: _NAME:=VALUE)",
    "ROS 1 node: subscribes to depth/image (16UC1 mm or 32FC1 m) with depth/camera_info, and with --colour\n"
    "to rgb/image; publishes people (rdsf_people/People), people/markers (visualization_msgs/MarkerArray)\n"
    "and /diagnostics. Parameters in the node's private namespace (~threshold, ~row_step, ...) are read as\n"
    "the options of the same names; an option on the command line wins. See docs/ros.md."};

int main(int argc, char** argv) {
  return rdsf::cli::run(kProgram.name, [&] {
    namespace po = rdsf::cli::po;
    rdsf::PeopleNodeOptions o;
    po::options_description options("rdsf_people (ROS parameters ~NAME, or options --NAME)");
    rdsf::cli::add_model_option(options, o.model,
                                "the model that scores candidates (the default, 'people', is the shipped model, "
                                "trained on synthetic data only)");
    rdsf::cli::add_models_dir_option(options, o.models_dir);
    rdsf::cli::add_decision_options(options, o.pipeline);
    rdsf::cli::add_threads_option(options, o.threads, "live workers analysing frames",
                                  "at most one frame waits per worker, a newer one replaces the oldest waiting "
                                  "(dropped, counted in /diagnostics)");
    rdsf::cli::add_table_options(options, rdsf::node_parameters(), o);
    options.add(rdsf::cli::analyser_options(o.pipeline.analyser));
    std::string background;
    options.add(rdsf::cli::background_options(background, o.pipeline.analyser.background_margins));
    options.add(rdsf::cli::tracking_options(o.pipeline.tracking));
    ros::init(argc, argv, kProgram.name);  // takes the ROS arguments (remappings, _NAME:=VALUE) out of argv
    std::vector<std::string> arguments = rdsf::arguments_with_parameters(argc, argv, options);
    std::vector<char*> argument_pointers;
    for (std::string& a : arguments) argument_pointers.push_back(a.data());
    po::variables_map values;
    if (!rdsf::cli::parse(static_cast<int>(argument_pointers.size()), argument_pointers.data(), kProgram, options, values)) {
      return 0;
    }
    o.feature_spec_given = !values["feature-spec"].defaulted();
    o.pipeline.analyser_given = rdsf::cli::given_analyser_options(values);
    // Waiting, a frame's colour is its own: a pair's stamps are close. Not waiting (the default), it is the
    // previous frame's: the default gap allows a frame period at 10 frames/s and up.
    if (o.colour_wait && values["colour-gap-ms"].defaulted()) o.colour_gap_ms = rdsf::kColourGapWaitingMs;
    rdsf::cli::apply_background(background, o.pipeline.analyser);
    return rdsf::run_people_node(o);
  });
}
