#include "ros/node_parameters.hpp"

namespace rdsf {

const ParameterTable<PeopleNodeOptions>& node_parameters() {
  using P = PeopleNodeOptions;
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
      computed_parameter<P, std::string>(
          "camera-info",
          "how a depth image finds its camera model on depth/camera_info: exact (the camera_info of its own stamp, "
          "as a driver publishes it) or latest (the newest camera_info received, which must name the image's "
          "optical frame; for bags and robots whose camera_info is stamped apart, e.g. a registered depth image "
          "with depth/camera_info remapped to the colour camera's; a depth image before the first camera_info "
          "waits for it, the newest one only)",
          [](const P& p) { return std::string(p.camera_info == CameraInfoPairing::latest ? "latest" : "exact"); },
          [](P& p, const std::string& word) {
            if (word == "exact") {
              p.camera_info = CameraInfoPairing::exact;
            } else if (word == "latest") {
              p.camera_info = CameraInfoPairing::latest;
            } else {
              refuse_parameter("camera-info", "'" + word + "' is not known (exact or latest)");
            }
          }),
      parameter("diagnostics-period", &P::diagnostics_period_s,
                "seconds between /diagnostics messages (drops, latency percentiles)", Range::above(0)),
  };
  return table;
}

}  // namespace rdsf
