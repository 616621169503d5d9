#pragma once
// Frames from OpenNI2: a recorded .oni file, read frame by frame as fast as the consumer asks (playback
// speed "manual": no frame is dropped, none is repeated), or a live device with depth registered to colour
// and depth/colour synchronisation on. The library's only use of OpenNI.h (rdsf-record, a program, is the
// other one).
//
// Recordings: every depth frame once, in order; index 0, 1, 2...; timestamp_us as recorded (OpenNI2's
// recorder starts each stream's clock at 0); colour is the recorded colour frame nearest in time. A
// recording whose depth stream lacks the cropping property (e.g. from OpenNI2's Dummy device) is refused
// with a one-line error: OpenNI2's file player would deliver none of its frames (docs/frames-and-openni.md, "What was wrong").
// Recorded frame numbers are checked, so a frame the player skips (damaged record) is an Error. Several
// sources may be open on one file at once, each playing independently.
// Live devices: the newest depth frame and the newest colour frame at each call.
// Every wait is bounded by `wait_timeout_ms`; a recording that stops early (truncated) ends in an Error.
// Camera model: the user's when FrameSourceOptions::camera_given; else from OpenNI2's horizontal field of
// view of the stream whose geometry the depth image has (the colour stream when depth is registered to
// colour, else the depth stream): f = width / 2 / tan(hfov / 2) for fx and fy, centre (w - 1) / 2,
// (h - 1) / 2, as ROS's openni2_camera does; description() says which.
#include <memory>
#include <string>

#include "rdsf/frame/frame_source.hpp"

namespace rdsf {

/// OpenNI2's last extended error on one line (its messages come with tabs and newlines).
std::string openni_last_error();

class OpenNISource : public FrameSource {
 public:
  /// `spec`: a path to an .oni file, "openni" for the first attached device, or a device URI.
  /// Throws Error naming the file or device when it cannot be opened or delivers no depth.
  OpenNISource(const std::string& spec, const FrameSourceOptions& options, int wait_timeout_ms = 2000);
  ~OpenNISource() override;
  OpenNISource(const OpenNISource&) = delete;
  OpenNISource& operator=(const OpenNISource&) = delete;

  bool next(DepthFrame& frame) override;
  std::string description() const override;
  std::optional<std::int64_t> frame_count() const override;
  /// A recording's index_frame_names(frame_count()); nothing for a live device.
  std::optional<std::vector<std::string>> frame_names() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rdsf
