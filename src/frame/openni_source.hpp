#pragma once
// Frames from OpenNI2: a recorded .oni file, read frame by frame as fast as the consumer asks (playback
// speed "manual": no frame is dropped, none is repeated), or a live device with depth registered to colour
// and depth/colour synchronisation on. This is the only place in the project that includes OpenNI.h.
#include <memory>
#include <string>

#include "frame/frame_source.hpp"

namespace rdsf {

class OpenNISource : public FrameSource {
 public:
  /// `spec`: a path to an .oni file, "openni" for the first attached device, or a device URI.
  /// Throws Error naming the file or device when it cannot be opened or delivers no depth.
  OpenNISource(const std::string& spec, const CameraModel& camera, int wait_timeout_ms = 2000);
  ~OpenNISource() override;
  OpenNISource(const OpenNISource&) = delete;
  OpenNISource& operator=(const OpenNISource&) = delete;

  bool next(DepthFrame& frame) override;
  std::string description() const override;
  std::optional<std::int64_t> frame_count() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rdsf
