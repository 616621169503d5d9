#include "frame/openni_source.hpp"

#include <cstring>
#include <filesystem>
#include <mutex>

#include <OpenNI.h>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace rdsf {
namespace {

std::string openni_error() {
  // OpenNI2's messages come with tabs and newlines; keep every message on one line.
  std::string text;
  for (const char* c = openni::OpenNI::getExtendedError(); c != nullptr && *c != '\0'; ++c) {
    const bool space = *c == '\n' || *c == '\r' || *c == '\t' || *c == ' ';
    if (space && (text.empty() || text.back() == ' ')) continue;
    text += space ? ' ' : *c;
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text.empty() ? "no details from OpenNI2" : text;
}

void initialise_openni_once(const std::string& where) {
  static std::once_flag once;
  static openni::Status status = openni::STATUS_OK;
  static std::string error;
  std::call_once(once, [] {
    status = openni::OpenNI::initialize();
    if (status != openni::STATUS_OK) error = openni_error();
  });
  if (status != openni::STATUS_OK) fail(where, "OpenNI2 cannot be initialised: " + error);
}

bool is_depth_format(openni::PixelFormat f) {
  return f == openni::PIXEL_FORMAT_DEPTH_1_MM || f == openni::PIXEL_FORMAT_DEPTH_100_UM;
}

// Copies a depth frame into millimetres (100-micrometre formats are divided by 10, rounding).
cv::Mat1w depth_to_mm(const openni::VideoFrameRef& f, const std::string& where) {
  const auto format = f.getVideoMode().getPixelFormat();
  if (!is_depth_format(format)) fail(where, "depth stream has a pixel format that is not depth");
  const cv::Mat1w view(f.getHeight(), f.getWidth(),
                       const_cast<std::uint16_t*>(static_cast<const std::uint16_t*>(f.getData())),
                       static_cast<std::size_t>(f.getStrideInBytes()));
  cv::Mat1w depth_mm;
  if (format == openni::PIXEL_FORMAT_DEPTH_100_UM) {
    view.convertTo(depth_mm, CV_16U, 0.1);
  } else {
    depth_mm = view.clone();
  }
  return depth_mm;
}

cv::Mat3b colour_to_bgr(const openni::VideoFrameRef& f, const std::string& where) {
  void* data = const_cast<void*>(f.getData());
  const auto stride = static_cast<std::size_t>(f.getStrideInBytes());
  cv::Mat3b bgr;
  switch (f.getVideoMode().getPixelFormat()) {
    case openni::PIXEL_FORMAT_RGB888:
      cv::cvtColor(cv::Mat(f.getHeight(), f.getWidth(), CV_8UC3, data, stride), bgr, cv::COLOR_RGB2BGR);
      break;
    case openni::PIXEL_FORMAT_GRAY8:
      cv::cvtColor(cv::Mat(f.getHeight(), f.getWidth(), CV_8UC1, data, stride), bgr, cv::COLOR_GRAY2BGR);
      break;
    case openni::PIXEL_FORMAT_YUV422:
      cv::cvtColor(cv::Mat(f.getHeight(), f.getWidth(), CV_8UC2, data, stride), bgr, cv::COLOR_YUV2BGR_UYVY);
      break;
    case openni::PIXEL_FORMAT_YUYV:
      cv::cvtColor(cv::Mat(f.getHeight(), f.getWidth(), CV_8UC2, data, stride), bgr, cv::COLOR_YUV2BGR_YUYV);
      break;
    default: fail(where, "colour stream has an unsupported pixel format");
  }
  return bgr;
}

}  // namespace

struct OpenNISource::Impl {
  std::string spec;
  std::string where;  // the name used in messages
  bool is_file = false;
  int wait_timeout_ms = 2000;
  CameraModel camera;
  openni::Device device;
  openni::VideoStream depth;
  openni::VideoStream colour;
  bool has_colour = false;
  std::int64_t total_frames = -1;  // files only
  std::int64_t delivered = 0;

  ~Impl() {
    if (colour.isValid()) {
      colour.stop();
      colour.destroy();
    }
    if (depth.isValid()) {
      depth.stop();
      depth.destroy();
    }
    if (device.isValid()) device.close();
  }

  // Waits (bounded) until `stream` has a frame, then reads it.
  void read(openni::VideoStream& stream, openni::VideoFrameRef& frame, const char* what) {
    openni::VideoStream* streams[] = {&stream};
    int ready = -1;
    if (openni::OpenNI::waitForAnyStream(streams, 1, &ready, wait_timeout_ms) != openni::STATUS_OK) {
      fail(where, std::string("no ") + what + " frame within " + std::to_string(wait_timeout_ms) +
                      " ms (" + openni_error() + ")");
    }
    if (stream.readFrame(&frame) != openni::STATUS_OK || !frame.isValid()) {
      fail(where, std::string("cannot read ") + what + " frame: " + openni_error());
    }
  }
};

OpenNISource::OpenNISource(const std::string& spec, const CameraModel& camera, int wait_timeout_ms)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.spec = spec;
  s.camera = camera;
  s.wait_timeout_ms = wait_timeout_ms;
  s.is_file = spec.size() > 4 && spec.compare(spec.size() - 4, 4, ".oni") == 0;
  s.where = s.is_file ? spec : (spec == "openni" ? std::string("OpenNI2 device") : "OpenNI2 device " + spec);

  if (s.is_file) {
    std::error_code ec;
    if (!std::filesystem::exists(spec, ec)) fail(spec, "no such file");
    if (!std::filesystem::is_regular_file(spec, ec)) fail(spec, "not a regular file");
    if (std::filesystem::file_size(spec, ec) < 16) fail(spec, "not an OpenNI recording (file too short)");
  }
  initialise_openni_once(s.where);

  const char* uri = (spec == "openni") ? openni::ANY_DEVICE : spec.c_str();
  if (s.device.open(uri) != openni::STATUS_OK) {
    if (s.is_file) fail(spec, "not a readable OpenNI recording (truncated or not .oni): " + openni_error());
    if (spec == "openni") fail(s.where, "no device attached (" + openni_error() + ")");
    fail(s.where, "cannot open device (" + openni_error() + ")");
  }
  if (!s.device.hasSensor(openni::SENSOR_DEPTH)) fail(s.where, "has no depth stream");
  if (s.depth.create(s.device, openni::SENSOR_DEPTH) != openni::STATUS_OK) {
    fail(s.where, "cannot create depth stream: " + openni_error());
  }
  if (s.device.hasSensor(openni::SENSOR_COLOR) &&
      s.colour.create(s.device, openni::SENSOR_COLOR) == openni::STATUS_OK) {
    s.has_colour = true;
  }

  if (s.is_file) {
    openni::PlaybackControl* playback = s.device.getPlaybackControl();
    if (playback == nullptr) fail(spec, "OpenNI2 offers no playback control for this file");
    // Manual speed: a frame becomes available when the program reads it, so none is dropped.
    playback->setSpeed(-1.0f);
    playback->setRepeatEnabled(false);
    s.total_frames = playback->getNumberOfFrames(s.depth);
    if (s.total_frames <= 0) fail(spec, "recording holds no depth frames");
  } else {
    // Live: millimetre depth at 640x480 when offered, registered to colour, synchronised.
    const openni::SensorInfo& info = s.depth.getSensorInfo();
    const auto& modes = info.getSupportedVideoModes();
    for (int i = 0; i < modes.getSize(); ++i) {
      if (modes[i].getPixelFormat() == openni::PIXEL_FORMAT_DEPTH_1_MM && modes[i].getResolutionX() == 640 &&
          modes[i].getResolutionY() == 480) {
        s.depth.setVideoMode(modes[i]);
        break;
      }
    }
    if (s.has_colour) {
      if (s.device.isImageRegistrationModeSupported(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR)) {
        s.device.setImageRegistrationMode(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR);
      }
      s.device.setDepthColorSyncEnabled(true);
    }
  }

  if (s.depth.start() != openni::STATUS_OK) fail(s.where, "cannot start depth stream: " + openni_error());
  if (s.has_colour && s.colour.start() != openni::STATUS_OK) {
    s.colour.destroy();
    s.has_colour = false;
  }
}

OpenNISource::~OpenNISource() = default;

bool OpenNISource::next(DepthFrame& frame) {
  Impl& s = *impl_;
  if (s.is_file && s.delivered >= s.total_frames) return false;
  openni::VideoFrameRef depth_frame;
  s.read(s.depth, depth_frame, "depth");
  frame.depth_mm = depth_to_mm(depth_frame, s.where);
  frame.bgr.release();
  if (s.has_colour) {
    openni::VideoFrameRef colour_frame;
    s.read(s.colour, colour_frame, "colour");
    cv::Mat3b bgr = colour_to_bgr(colour_frame, s.where);
    if (bgr.size() != frame.depth_mm.size()) cv::resize(bgr, bgr, frame.depth_mm.size(), 0, 0, cv::INTER_AREA);
    frame.bgr = bgr;
  }
  frame.index = s.delivered;
  frame.name = std::to_string(s.delivered);
  frame.timestamp_us = static_cast<std::int64_t>(depth_frame.getTimestamp());
  frame.camera = (frame.depth_mm.cols == s.camera.width_px && frame.depth_mm.rows == s.camera.height_px)
                     ? s.camera
                     : s.camera.scaled_to(frame.depth_mm.cols, frame.depth_mm.rows);
  ++s.delivered;
  return true;
}

std::string OpenNISource::description() const {
  const Impl& s = *impl_;
  std::string text = s.where;
  if (s.is_file) text += " (" + std::to_string(s.total_frames) + " frames)";
  return text + (s.has_colour ? ", depth and colour" : ", depth only");
}

std::optional<std::int64_t> OpenNISource::frame_count() const {
  if (impl_->is_file) return impl_->total_frames;
  return std::nullopt;
}

}  // namespace rdsf
