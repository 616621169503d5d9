#pragma once
// Pairs the depth frames of a live stream with the colour images of another topic by time stamp, without
// looking ahead more than one frame. Both topics arrive in stamp order (each on its own connection, so a
// depth frame may come before or after its colour). Rules, gap = |depth stamp - colour stamp|:
//   - a depth frame takes the waiting colour image of smallest gap when that gap <= max_gap_us (colour
//     images older than the one taken are discarded);
//   - otherwise it waits for its colour, unless its colour cannot come any more: a colour image newer than
//     its stamp + max_gap_us is already here, or no colour image came within stale_after_us of its stamp
//     (a dead colour publisher; none at all: stale_after_us after the first depth frame); then it goes on
//     without colour;
//   - a waiting depth frame goes on without colour when the next depth frame arrives or a colour image
//     newer than its stamp + max_gap_us arrives (a frame without colour in a stream with colour).
// So a frame waits at most until the next frame of either topic, and every depth frame comes out once, in
// arrival order. "Newer" compares with the colour image that arrived last, so stamps that start again (a
// bag played in a loop, a restarted camera) cost one frame its colour, not all the following ones.
//   With wait off (ColourWait::never: the node's --colour-wait false) a depth frame never waits: it takes the
// waiting colour image of smallest gap when that gap <= max_gap_us, else goes on at once without colour; the
// image taken stays for the next depth frame as well (whose own may come after it). A colour image arrives
// after its depth frame (another connection, a larger message), so the one taken is then the previous
// frame's: the gap is about one frame period (33 ms at 30 frames/s), and max_gap_us must allow it. The price
// of the latency saved: colour histograms of a box taken from an image up to one frame older than the depth.
// Not thread-safe (the node calls it from its one callback thread).
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/frame/depth_frame.hpp"

namespace rdsf {

struct PairedFrame {
  DepthFrame frame;        ///< with .bgr set when a colour image was paired
  std::int64_t gap_us = -1;  ///< |depth - colour stamp| of the pair, -1 without colour
};

/// Whether a depth frame may wait for its colour image (see above).
enum class ColourWait { until_paired, never };

class ColourPairing {
 public:
  explicit ColourPairing(std::int64_t max_gap_us, std::int64_t stale_after_us = 1000000, std::size_t history = 8,
                         ColourWait wait = ColourWait::until_paired);

  /// A depth frame arrives (its timestamp_us is the stamp). Returns the frames that go on now, in order.
  std::vector<PairedFrame> add_depth(DepthFrame frame);
  /// A colour image arrives. Returns the frames that go on now (the waiting one, with or without colour).
  std::vector<PairedFrame> add_colour(std::int64_t stamp_us, cv::Mat3b bgr);
  /// The waiting frame, without colour (at the end of a stream).
  std::vector<PairedFrame> flush();

 private:
  struct Colour {
    std::int64_t stamp_us;
    cv::Mat3b bgr;
  };
  std::int64_t max_gap_us_, stale_after_us_;
  std::size_t history_;
  ColourWait wait_;
  std::deque<Colour> colours_;  ///< waiting colour images, oldest first
  std::optional<std::int64_t> newest_colour_us_, first_depth_us_;  ///< last colour to arrive; first depth frame
  std::optional<DepthFrame> waiting_;
};

}  // namespace rdsf
