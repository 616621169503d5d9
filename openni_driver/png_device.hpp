#pragma once
// The virtual sensor: a folder of depth (and colour) PNGs served as an OpenNI2 device. Once a stream is
// started, a frame thread sends one frame per period (1/fps, first frame one period after the start) to
// every started stream, with frame index i+1 and timestamp i/fps seconds in microseconds, until the last
// PNG; then the device goes quiet, as an unplugged camera would. A frame sent late on a busy machine
// delays the following ones (at least half a period apart), so frames never come in bursts.
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <Driver/OniDriverAPI.h>

#include "png_device_uri.hpp"
#include "png_sequence.hpp"

namespace rdsf::openni_driver {

class PngStream;

class PngDevice : public oni::driver::DeviceBase {
 public:
  /// `options`: what the device offers (fps, depth, cropping property), from its address.
  PngDevice(PngSequence sequence, const PngDeviceUri& options, oni::driver::DriverServices& services);
  ~PngDevice() override;
  PngDevice(const PngDevice&) = delete;
  PngDevice& operator=(const PngDevice&) = delete;

  OniStatus getSensorInfoList(OniSensorInfo** sensors, int* sensor_count) override;
  oni::driver::StreamBase* createStream(OniSensorType sensor_type) override;
  void destroyStream(oni::driver::StreamBase* stream) override;
  OniStatus getProperty(int property_id, void* data, int* data_size) override;
  OniStatus setProperty(int property_id, const void* data, int data_size) override;
  OniBool isPropertySupported(int property_id) override;
  OniBool isImageRegistrationModeSupported(OniImageRegistrationMode mode) override;

  /// Called by a stream when it starts or stops: the frame thread runs while any stream is started.
  void stream_started();
  void stream_stopped();

 private:
  void run_frames();
  void stop_frame_thread();
  bool any_started_locked() const;

  PngSequence sequence_;
  PngDeviceUri options_;
  oni::driver::DriverServices& services_;
  std::vector<OniVideoMode> modes_;  // one per sensor, in the order of sensors_
  std::vector<OniSensorInfo> sensors_;
  OniImageRegistrationMode registration_ = ONI_IMAGE_REGISTRATION_OFF;

  std::mutex mutex_;  // guards streams_, next_frame_, stop_, thread_
  std::condition_variable wake_;
  std::vector<PngStream*> streams_;
  std::size_t next_frame_ = 0;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace rdsf::openni_driver
