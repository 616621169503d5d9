#pragma once
// One stream of the virtual sensor (depth in millimetres, or RGB colour), with the properties a real
// sensor's stream reports. Among them is the cropping property: OpenNI2's recorder stores it only when
// the stream offers it, and OpenNI2's file player (OniFile) drops every frame of a recording that lacks
// it - the cause of "recorded fine, plays back no frames" (README.md, "What was wrong").
#include <atomic>
#include <cstdint>

#include <Driver/OniDriverAPI.h>
#include <opencv2/core.hpp>

namespace rdsf::openni_driver {

class PngDevice;

class PngStream : public oni::driver::StreamBase {
 public:
  /// `mode`: the one video mode of the stream (pixel format DEPTH_1_MM or RGB888); `offers_cropping`:
  /// whether the cropping property is offered (always, except to reproduce the playback fault);
  /// `hfov_deg`: the horizontal field of view reported (0: 525 px focal length at 640 px wide).
  PngStream(PngDevice& device, OniSensorType sensor_type, const OniVideoMode& mode, bool offers_cropping,
            double hfov_deg);
  ~PngStream() override;
  PngStream(const PngStream&) = delete;
  PngStream& operator=(const PngStream&) = delete;

  OniStatus start() override;
  void stop() override;
  OniStatus getProperty(int property_id, void* data, int* data_size) override;
  OniStatus setProperty(int property_id, const void* data, int data_size) override;
  OniBool isPropertySupported(int property_id) override;
  int getRequiredFrameSize() override;

  bool started() const { return started_; }
  OniSensorType sensor_type() const { return sensor_type_; }
  /// Sends `image` (CV_16UC1 depth or CV_8UC3 RGB of the mode's size) as one frame. Called on the device's
  /// frame thread only.
  void deliver(const cv::Mat& image, int frame_index, std::uint64_t timestamp_us);

 private:
  int bytes_per_pixel() const;

  PngDevice& device_;
  OniSensorType sensor_type_;
  OniVideoMode mode_;
  bool offers_cropping_;
  double focal_px_;  // from hfov_deg, or 525 px at 640 px wide; square pixels
  std::atomic<bool> started_{false};
};

}  // namespace rdsf::openni_driver
