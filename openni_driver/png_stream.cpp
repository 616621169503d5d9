#include "png_stream.hpp"

#include <cmath>
#include <cstring>

#include "png_device.hpp"

namespace rdsf::openni_driver {
namespace {

// Field of view of the workbench's default camera model (Kinect v1: focal length 525 px at 640x480).
constexpr double kFocalPxAt640 = 525.0;
constexpr int kMaxDepthMm = 10000;

template <typename T>
OniStatus put(void* data, int* data_size, const T& value) {
  if (data == nullptr || data_size == nullptr || *data_size < static_cast<int>(sizeof(T))) {
    return ONI_STATUS_BAD_PARAMETER;
  }
  std::memcpy(data, &value, sizeof(T));
  *data_size = static_cast<int>(sizeof(T));
  return ONI_STATUS_OK;
}

template <typename T>
bool take(const void* data, int data_size, T& value) {
  if (data == nullptr || data_size != static_cast<int>(sizeof(T))) return false;
  std::memcpy(&value, data, sizeof(T));
  return true;
}

}  // namespace

PngStream::PngStream(PngDevice& device, OniSensorType sensor_type, const OniVideoMode& mode,
                     bool offers_cropping, double hfov_deg)
    : device_(device),
      sensor_type_(sensor_type),
      mode_(mode),
      offers_cropping_(offers_cropping),
      focal_px_(hfov_deg > 0.0 ? mode.resolutionX / 2.0 / std::tan(hfov_deg * M_PI / 360.0)
                               : kFocalPxAt640 * mode.resolutionX / 640.0) {}

PngStream::~PngStream() { stop(); }

OniStatus PngStream::start() {
  if (!started_.exchange(true)) device_.stream_started();
  return ONI_STATUS_OK;
}

void PngStream::stop() {
  if (started_.exchange(false)) device_.stream_stopped();
}

int PngStream::bytes_per_pixel() const { return mode_.pixelFormat == ONI_PIXEL_FORMAT_RGB888 ? 3 : 2; }

int PngStream::getRequiredFrameSize() { return mode_.resolutionX * mode_.resolutionY * bytes_per_pixel(); }

OniBool PngStream::isPropertySupported(int property_id) {
  switch (property_id) {
    case ONI_STREAM_PROPERTY_CROPPING: return offers_cropping_ ? TRUE : FALSE;
    case ONI_STREAM_PROPERTY_VIDEO_MODE:
    case ONI_STREAM_PROPERTY_HORIZONTAL_FOV:
    case ONI_STREAM_PROPERTY_VERTICAL_FOV:
    case ONI_STREAM_PROPERTY_STRIDE:
    case ONI_STREAM_PROPERTY_MIRRORING: return TRUE;
    case ONI_STREAM_PROPERTY_MAX_VALUE:
    case ONI_STREAM_PROPERTY_MIN_VALUE: return sensor_type_ == ONI_SENSOR_DEPTH ? TRUE : FALSE;
    default: return FALSE;
  }
}

OniStatus PngStream::getProperty(int property_id, void* data, int* data_size) {
  switch (property_id) {
    case ONI_STREAM_PROPERTY_VIDEO_MODE: return put(data, data_size, mode_);
    case ONI_STREAM_PROPERTY_CROPPING: {
      if (!offers_cropping_) return ONI_STATUS_NOT_SUPPORTED;
      OniCropping cropping{};
      cropping.enabled = FALSE;
      cropping.width = mode_.resolutionX;
      cropping.height = mode_.resolutionY;
      return put(data, data_size, cropping);
    }
    case ONI_STREAM_PROPERTY_HORIZONTAL_FOV:
      return put(data, data_size, static_cast<float>(2.0 * std::atan(mode_.resolutionX / (2.0 * focal_px_))));
    case ONI_STREAM_PROPERTY_VERTICAL_FOV:
      return put(data, data_size, static_cast<float>(2.0 * std::atan(mode_.resolutionY / (2.0 * focal_px_))));
    case ONI_STREAM_PROPERTY_STRIDE: return put(data, data_size, mode_.resolutionX * bytes_per_pixel());
    case ONI_STREAM_PROPERTY_MIRRORING: return put(data, data_size, OniBool{FALSE});
    case ONI_STREAM_PROPERTY_MAX_VALUE:
      if (sensor_type_ != ONI_SENSOR_DEPTH) return ONI_STATUS_NOT_SUPPORTED;
      return put(data, data_size, kMaxDepthMm);
    case ONI_STREAM_PROPERTY_MIN_VALUE:
      if (sensor_type_ != ONI_SENSOR_DEPTH) return ONI_STATUS_NOT_SUPPORTED;
      return put(data, data_size, 0);
    default: return ONI_STATUS_NOT_SUPPORTED;
  }
}

OniStatus PngStream::setProperty(int property_id, const void* data, int data_size) {
  // The frames are files: only the values the stream already has are accepted.
  switch (property_id) {
    case ONI_STREAM_PROPERTY_VIDEO_MODE: {
      OniVideoMode mode{};
      if (!take(data, data_size, mode)) return ONI_STATUS_BAD_PARAMETER;
      const bool same = mode.pixelFormat == mode_.pixelFormat && mode.resolutionX == mode_.resolutionX &&
                        mode.resolutionY == mode_.resolutionY;
      return same ? ONI_STATUS_OK : ONI_STATUS_NOT_SUPPORTED;
    }
    case ONI_STREAM_PROPERTY_CROPPING: {
      if (!offers_cropping_) return ONI_STATUS_NOT_SUPPORTED;
      OniCropping cropping{};
      if (!take(data, data_size, cropping)) return ONI_STATUS_BAD_PARAMETER;
      return cropping.enabled ? ONI_STATUS_NOT_SUPPORTED : ONI_STATUS_OK;
    }
    case ONI_STREAM_PROPERTY_MIRRORING: {
      OniBool mirroring = FALSE;
      if (!take(data, data_size, mirroring)) return ONI_STATUS_BAD_PARAMETER;
      return mirroring ? ONI_STATUS_NOT_SUPPORTED : ONI_STATUS_OK;
    }
    default: return ONI_STATUS_NOT_SUPPORTED;
  }
}

void PngStream::deliver(const cv::Mat& image, int frame_index, std::uint64_t timestamp_us) {
  if (!started_) return;
  OniFrame* frame = getServices().acquireFrame();
  if (frame == nullptr) return;
  const int row_bytes = mode_.resolutionX * bytes_per_pixel();
  auto* out = static_cast<unsigned char*>(frame->data);
  for (int y = 0; y < mode_.resolutionY; ++y) {
    std::memcpy(out + static_cast<std::size_t>(y) * static_cast<std::size_t>(row_bytes), image.ptr(y),
                static_cast<std::size_t>(row_bytes));
  }
  frame->dataSize = row_bytes * mode_.resolutionY;
  frame->sensorType = sensor_type_;
  frame->timestamp = timestamp_us;
  frame->frameIndex = frame_index;
  frame->width = mode_.resolutionX;
  frame->height = mode_.resolutionY;
  frame->videoMode = mode_;
  frame->croppingEnabled = FALSE;
  frame->cropOriginX = 0;
  frame->cropOriginY = 0;
  frame->stride = row_bytes;
  raiseNewFrame(frame);
  getServices().releaseFrame(frame);
}

}  // namespace rdsf::openni_driver
