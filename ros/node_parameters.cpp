#include "ros/node_parameters.hpp"

#include <string>
#include <utility>

namespace rdsf {
namespace {

using P = PeopleNodeOptions;

/// A row whose value is one of two words, each standing for a value of `member`.
template <typename T>
Parameter<P> two_words(const std::string& name, const std::string& help, T P::*member, std::pair<T, std::string> first,
                       std::pair<T, std::string> second) {
  return computed_parameter<P, std::string>(
      name, help, [=](const P& p) { return p.*member == second.first ? second.second : first.second; },
      [=](P& p, const std::string& word) {
        if (word != first.second && word != second.second) {
          refuse_parameter(name, "'" + word + "' is not known (" + first.second + " or " + second.second + ")");
        }
        p.*member = word == second.second ? second.first : first.first;
      });
}

}  // namespace

const ParameterTable<PeopleNodeOptions>& node_parameters() {
  static const ParameterTable<P> table = {
      parameter("colour", &P::colour,
                "also subscribe to rgb/image (registered to the depth image, same size) and pair it by stamp: tracking "
                "compares colour histograms"),
      parameter("colour-gap-ms", &P::colour_gap_ms,
                "largest stamp difference (ms) of a depth and a colour image that are a pair (with --colour-wait "
                "true: 15 unless given)",
                Range::at_least(0)),
      parameter("colour-wait", &P::colour_wait,
                "false: a depth frame takes the colour image already there (the previous frame's, one frame period "
                "older) and never waits, for the lowest latency (tracking measured the same); true: it waits for the "
                "colour image of its own stamp (until the next frame at most)"),
      two_words("camera-info",
                "how a depth image finds its camera model on depth/camera_info: exact (the camera_info of its own "
                "stamp, as a driver publishes it) or latest (the newest camera_info received, which must name the "
                "image's optical frame; for bags and robots whose camera_info is stamped apart, e.g. a registered "
                "depth image with depth/camera_info remapped to the colour camera's; a depth image before the first "
                "camera_info waits for it, the newest one only)",
                &P::camera_info, {CameraInfoPairing::exact, "exact"}, {CameraInfoPairing::latest, "latest"}),
      two_words("depth-transport",
                "raw (sensor_msgs/Image on depth/image) or compressedDepth (sensor_msgs/CompressedImage on "
                "depth/image/compressedDepth, image_transport's name: png or rvl, 16UC1 or 32FC1), decoded by the node",
                &P::compressed_depth, {false, "raw"}, {true, "compressedDepth"}),
      two_words("colour-transport",
                "raw (sensor_msgs/Image on rgb/image) or compressed (sensor_msgs/CompressedImage on "
                "rgb/image/compressed: jpeg or png), decoded by the node",
                &P::compressed_colour, {false, "raw"}, {true, "compressed"}),
      parameter("diagnostics-period", &P::diagnostics_period_s,
                "seconds between /diagnostics messages (drops, latency percentiles)", Range::above(0)),
  };
  return table;
}

}  // namespace rdsf
