// The table of TrackingParams (core/parameter_table.hpp): the tracker's options, each declared once. The
// thesis gives these values no departure, so no row has a thesis value.
#include "rdsf/tracking/tracker.hpp"

namespace rdsf {

const ParameterTable<TrackingParams>& tracking_parameters() {
  using P = TrackingParams;
  static const ParameterTable<P> table = {
      parameter("threshold-lkh", &P::threshold_lkh,
                "a detection matches a person when lkh = Bhattacharyya distance + d_cm/98 - 1/49 <= this"),
      parameter("max-missed-frames", &P::max_missed_frames,
                "a person unmatched for more frames is not matched again (0: never forgotten)", Range::at_least(0)),
      parameter("histogram-bins", &P::histogram_bins, "colour histogram bins per channel", Range::between(1, 256)),
  };
  return table;
}

}  // namespace rdsf
