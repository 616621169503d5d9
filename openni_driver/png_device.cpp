#include "png_device.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <utility>

#include "png_stream.hpp"

namespace rdsf::openni_driver {

PngDevice::PngDevice(PngSequence sequence, const PngDeviceUri& options, oni::driver::DriverServices& services)
    : sequence_(std::move(sequence)), options_(options), services_(services) {
  OniVideoMode mode{};
  mode.resolutionX = sequence_.width_px();
  mode.resolutionY = sequence_.height_px();
  mode.fps = options_.fps;
  std::vector<OniSensorType> types;
  if (options_.depth) {
    mode.pixelFormat = ONI_PIXEL_FORMAT_DEPTH_1_MM;
    modes_.push_back(mode);
    types.push_back(ONI_SENSOR_DEPTH);
  }
  if (sequence_.has_colour()) {
    mode.pixelFormat = ONI_PIXEL_FORMAT_RGB888;
    modes_.push_back(mode);
    types.push_back(ONI_SENSOR_COLOR);
  }
  // The sensor list points into modes_, which no longer changes.
  for (std::size_t i = 0; i < types.size(); ++i) sensors_.push_back(OniSensorInfo{types[i], 1, &modes_[i]});
}

PngDevice::~PngDevice() {
  stop_frame_thread();
  std::vector<PngStream*> left;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    left.swap(streams_);
  }
  for (PngStream* stream : left) delete stream;
}

OniStatus PngDevice::getSensorInfoList(OniSensorInfo** sensors, int* sensor_count) {
  *sensors = sensors_.data();
  *sensor_count = static_cast<int>(sensors_.size());
  return ONI_STATUS_OK;
}

oni::driver::StreamBase* PngDevice::createStream(OniSensorType sensor_type) {
  const OniVideoMode* mode = nullptr;
  for (const OniSensorInfo& sensor : sensors_) {
    if (sensor.sensorType == sensor_type) mode = sensor.pSupportedVideoModes;
  }
  if (mode == nullptr) {
    services_.errorLoggerAppend("%s: the virtual sensor has no stream of sensor type %d",
                                sequence_.folder().c_str(), static_cast<int>(sensor_type));
    return nullptr;
  }
  auto* stream = new PngStream(*this, sensor_type, *mode, options_.cropping, options_.hfov_deg);
  std::lock_guard<std::mutex> lock(mutex_);
  streams_.push_back(stream);
  return stream;
}

void PngDevice::destroyStream(oni::driver::StreamBase* stream) {
  auto* png_stream = static_cast<PngStream*>(stream);
  png_stream->stop();
  {
    // Taking the lock waits for a delivery in progress to finish.
    std::lock_guard<std::mutex> lock(mutex_);
    streams_.erase(std::remove(streams_.begin(), streams_.end(), png_stream), streams_.end());
  }
  delete png_stream;
}

OniBool PngDevice::isPropertySupported(int property_id) {
  return property_id == ONI_DEVICE_PROPERTY_IMAGE_REGISTRATION ? TRUE : FALSE;
}

OniStatus PngDevice::getProperty(int property_id, void* data, int* data_size) {
  if (property_id != ONI_DEVICE_PROPERTY_IMAGE_REGISTRATION) return ONI_STATUS_NOT_SUPPORTED;
  if (data == nullptr || data_size == nullptr || *data_size < static_cast<int>(sizeof(registration_))) {
    return ONI_STATUS_BAD_PARAMETER;
  }
  std::memcpy(data, &registration_, sizeof(registration_));
  *data_size = static_cast<int>(sizeof(registration_));
  return ONI_STATUS_OK;
}

OniStatus PngDevice::setProperty(int property_id, const void* data, int data_size) {
  if (property_id != ONI_DEVICE_PROPERTY_IMAGE_REGISTRATION) return ONI_STATUS_NOT_SUPPORTED;
  if (data == nullptr || data_size != static_cast<int>(sizeof(registration_))) return ONI_STATUS_BAD_PARAMETER;
  OniImageRegistrationMode mode = ONI_IMAGE_REGISTRATION_OFF;
  std::memcpy(&mode, data, sizeof(mode));
  if (!isImageRegistrationModeSupported(mode)) return ONI_STATUS_NOT_SUPPORTED;
  registration_ = mode;
  return ONI_STATUS_OK;
}

OniBool PngDevice::isImageRegistrationModeSupported(OniImageRegistrationMode mode) {
  // The PNG colour is registered to depth already: both modes deliver the same pixels.
  return (mode == ONI_IMAGE_REGISTRATION_OFF || mode == ONI_IMAGE_REGISTRATION_DEPTH_TO_COLOR) ? TRUE : FALSE;
}

bool PngDevice::any_started_locked() const {
  return std::any_of(streams_.begin(), streams_.end(), [](const PngStream* s) { return s->started(); });
}

void PngDevice::stream_started() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (thread_.joinable()) return;
  stop_ = false;
  thread_ = std::thread([this] { run_frames(); });
}

void PngDevice::stream_stopped() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (any_started_locked()) return;
  }
  stop_frame_thread();
}

void PngDevice::stop_frame_thread() {
  std::thread finished;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
    finished.swap(thread_);
  }
  wake_.notify_all();
  if (!finished.joinable()) return;
  if (finished.get_id() == std::this_thread::get_id()) {
    finished.detach();  // stopped from a frame callback: the loop ends on its own
  } else {
    finished.join();
  }
}

void PngDevice::run_frames() {
  using clock = std::chrono::steady_clock;
  const auto period = std::chrono::microseconds(1000000 / options_.fps);
  auto due = clock::now() + period;
  // A late frame (a busy machine) is followed by the next one at least half a period later, as a camera
  // would: frames never arrive in bursts that a reader could not take one by one.
  const auto shortest_gap = period / 2;
  for (;;) {
    std::size_t index = 0;
    bool want_depth = false;
    bool want_colour = false;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      if (wake_.wait_until(lock, due, [this] { return stop_; })) return;
      if (next_frame_ >= sequence_.size()) return;  // the last PNG was sent: the device goes quiet
      index = next_frame_++;
      for (const PngStream* s : streams_) {
        if (!s->started()) continue;
        want_depth = want_depth || s->sensor_type() == ONI_SENSOR_DEPTH;
        want_colour = want_colour || s->sensor_type() == ONI_SENSOR_COLOR;
      }
    }
    due = std::max(due + period, clock::now() + shortest_gap);
    cv::Mat depth_mm;
    cv::Mat rgb;
    std::string error;
    const bool read = (!want_depth || sequence_.read_depth(index, depth_mm, error)) &&
                      (!want_colour || sequence_.read_rgb(index, rgb, error));
    if (!read) {
      services_.log(3, __FILE__, __LINE__, "rdsf-png", error.c_str());
      std::lock_guard<std::mutex> lock(mutex_);
      next_frame_ = sequence_.size();  // a broken file ends the sequence
      return;
    }
    const int frame_index = static_cast<int>(index) + 1;
    const auto timestamp_us = static_cast<std::uint64_t>(index) * 1000000ULL / static_cast<std::uint64_t>(options_.fps);
    std::lock_guard<std::mutex> lock(mutex_);
    for (PngStream* s : streams_) {
      if (!s->started()) continue;
      s->deliver(s->sensor_type() == ONI_SENSOR_DEPTH ? depth_mm : rgb, frame_index, timestamp_us);
    }
  }
}

}  // namespace rdsf::openni_driver
