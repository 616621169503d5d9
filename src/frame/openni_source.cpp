#include "rdsf/frame/openni_source.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include <OpenNI.h>
#include <opencv2/imgproc.hpp>

#include "rdsf/core/error.hpp"

namespace rdsf {

// OpenNI2's messages come with tabs and newlines; keep every message on one line.
std::string openni_last_error() {
  std::string text;
  for (const char* c = openni::OpenNI::getExtendedError(); c != nullptr && *c != '\0'; ++c) {
    const bool space = *c == '\n' || *c == '\r' || *c == '\t' || *c == ' ';
    if (space && (text.empty() || text.back() == ' ')) continue;
    text += space ? ' ' : *c;
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text.empty() ? "no details from OpenNI2" : text;
}

namespace {

std::string openni_error() { return openni_last_error(); }

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

// A frame taken off a stream and converted, waiting to be paired.
struct DepthPending {
  cv::Mat1w depth_mm;
  std::int64_t timestamp_us = 0;
};
struct ColourPending {
  cv::Mat3b bgr;
  std::int64_t timestamp_us = 0;
};

// OpenNI2 keeps one device per address, so two sources opened on the same file name would share one
// player: every frame goes to both, and a wait of one advances the other (frames are lost). Each open
// source of a recording therefore gets an address of its own for the same file: the path itself, then
// "<folder>/./<name>", "<folder>/././<name>"...
class RecordingAddresses {
 public:
  /// Returns the address for `path` and the slot to release.
  static std::string acquire(const std::string& path, std::string& key, int& slot) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path full = fs::weakly_canonical(fs::absolute(path, ec), ec);
    if (full.empty()) full = path;
    key = full.string();
    std::lock_guard<std::mutex> lock(mutex());
    std::set<int>& used = slots()[key];
    slot = 0;
    while (used.count(slot) != 0) ++slot;
    used.insert(slot);
    std::string folder = full.parent_path().string();
    for (int i = 0; i < slot; ++i) folder += "/.";
    return folder + "/" + full.filename().string();
  }
  static void release(const std::string& key, int slot) {
    std::lock_guard<std::mutex> lock(mutex());
    auto it = slots().find(key);
    if (it == slots().end()) return;
    it->second.erase(slot);
    if (it->second.empty()) slots().erase(it);
  }

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static std::map<std::string, std::set<int>>& slots() {
    static std::map<std::string, std::set<int>> s;
    return s;
  }
};

// True when the stream reports the cropping property. OpenNI2's recorder stores it only when the recorded
// stream offers it, and OpenNI2's file player (OniFile, PlayerStream) silently drops every frame of a
// stream whose recording lacks it: waits then time out although the frame count is right. Recordings of
// the Dummy device, among others, are made that way (docs/frames-and-openni.md, "What was wrong").
bool reports_cropping(const openni::VideoStream& stream) {
  OniCropping cropping{};
  return stream.getProperty(openni::STREAM_PROPERTY_CROPPING, &cropping) == openni::STATUS_OK;
}

// The camera model of an image `width` x `height` whose horizontal field of view is `hfov_rad`, as ROS's
// openni2_camera takes it: square pixels (a sensor's reported vertical field of view is often rounded
// differently), focal length rounded to 0.001 px (the property is a float), the principal point at the
// centre (CameraModel::from_field_of_view). Nothing when the angle is not in (0, pi).
std::optional<CameraModel> camera_from_field_of_view(float hfov_rad, int width, int height) {
  if (!(hfov_rad > 0.0f && hfov_rad < static_cast<float>(M_PI)) || width <= 0 || height <= 0) return std::nullopt;
  CameraModel camera = CameraModel::from_field_of_view(width, height, hfov_rad * 180.0 / M_PI);
  camera.fx_px = camera.fy_px = std::round(camera.fx_px * 1000.0) / 1000.0;
  return camera;
}

}  // namespace

struct OpenNISource::Impl {
  std::string spec;
  std::string where;  // the name used in messages
  bool is_file = false;
  int wait_timeout_ms = 2000;
  CameraModel camera;
  std::string camera_note;  // where the camera model came from, for description()
  openni::Device device;
  openni::VideoStream depth;
  openni::VideoStream colour;
  bool has_colour = false;
  std::string colour_note;         // why a recorded colour stream is not used
  std::int64_t total_frames = -1;  // files only: depth frames in the recording
  std::int64_t colour_total = -1;  // files only: colour frames in the recording
  std::int64_t depth_received = 0;
  std::int64_t colour_received = 0;
  std::int64_t delivered = 0;
  std::deque<DepthPending> depth_queue;
  std::deque<ColourPending> colour_queue;
  cv::Mat3b last_colour;

  std::chrono::steady_clock::time_point opened_at;  // files: when the player was opened
  std::string address_key;  // files: the RecordingAddresses slot this source holds
  int address_slot = -1;
  static constexpr int kMaxReopensPerFrame = 3;
  int reopened_for_frame = 0;  // files: recoveries since the last frame delivered

  ~Impl() { close_all(); }

  // The camera model frames carry: the user's when given, else the one of OpenNI2's field of view of the
  // stream whose geometry the depth image has. That is the colour stream when depth is registered to
  // colour: a live device is set so above when it can be; a recording with a colour stream is taken as
  // registered when OpenNI2's player does not report the registration (as rdsf-record records). Else it
  // is the depth stream (a Kinect v1's unregistered depth: about 58 degrees, f about 575 px; registered,
  // 62.7 degrees, f 525 px). A stream that reports no usable angle leaves the fallback model.
  void choose_camera(const FrameSourceOptions& options) {
    if (options.camera_given) {
      camera_note = "camera model given (" + camera.describe() + ")";
      return;
    }
    openni::ImageRegistrationMode registration = openni::IMAGE_REGISTRATION_OFF;
    const bool reported = device.getProperty(openni::DEVICE_PROPERTY_IMAGE_REGISTRATION, &registration) ==
                          openni::STATUS_OK;
    const bool registered =
        has_colour && (reported ? registration == openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR : is_file);
    const openni::VideoStream& geometry = registered ? colour : depth;
    const openni::VideoMode mode = depth.getVideoMode();
    float hfov_rad = 0.0f;
    std::optional<CameraModel> model;
    if (geometry.getProperty(openni::STREAM_PROPERTY_HORIZONTAL_FOV, &hfov_rad) == openni::STATUS_OK) {
      model = camera_from_field_of_view(hfov_rad, mode.getResolutionX(), mode.getResolutionY());
    }
    if (!model) {
      camera_note = "no field of view reported, camera model " + camera.describe();
      return;
    }
    camera = *model;
    camera_note = std::string("camera model from OpenNI2's field of view of the ") +
                  (registered ? "colour stream (depth registered to colour)" : "depth stream") + " (" +
                  camera.describe() + ")";
  }

  // Stops and releases streams, device and address; the counters stay (reopen_recording uses them).
  void close_all() {
    if (is_file && device.isValid()) {
      // OpenNI2's file player marks its thread running only once the thread is under way, so a close()
      // that comes first is missed: close() then waits 3 s and kills the thread. Opening and closing at
      // once happens when a recording is refused (no depth...): give the thread the moment it needs.
      std::this_thread::sleep_until(opened_at + std::chrono::milliseconds(50));
    }
    // Both streams stop before either is destroyed, so the player never runs with a stream half gone;
    // streams go before the device, whose close() joins the file player's thread.
    if (colour.isValid()) colour.stop();
    if (depth.isValid()) depth.stop();
    if (colour.isValid()) colour.destroy();
    if (depth.isValid()) depth.destroy();
    if (device.isValid()) device.close();
    if (address_slot >= 0) RecordingAddresses::release(address_key, address_slot);
    address_slot = -1;
  }

  // Files: manual speed, so the player reads the next recorded frame only when a wait asks for one and
  // frames come as fast as the program reads them. Repeat on, although nothing is read past the last
  // frame: without repeat, OpenNI2's player thread spins at the end of the file, walking its stream list
  // without a lock, and destroying a stream then crashed about one run in twenty at shutdown. With repeat
  // it rewinds and parks, waiting for a trigger that never comes. accept_frame() catches any replay.
  openni::PlaybackControl& manual_playback() {
    openni::PlaybackControl* playback = device.getPlaybackControl();
    if (playback == nullptr) fail(where, "OpenNI2 offers no playback control for this file");
    if (playback->setSpeed(-1.0f) != openni::STATUS_OK || playback->setRepeatEnabled(true) != openni::STATUS_OK) {
      fail(where, "cannot set manual playback: " + openni_error());
    }
    return *playback;
  }

  // Files: opens the recording under an address of this source's own (RecordingAddresses).
  bool open_recording() {
    const std::string address = RecordingAddresses::acquire(spec, address_key, address_slot);
    opened_at = std::chrono::steady_clock::now();
    return device.open(address.c_str()) == openni::STATUS_OK;
  }

  // Files, after the player skipped a frame: a new player from the start of the file; the frames already
  // taken come again and accept_frame() drops them.
  void reopen_recording() {
    const bool with_colour = has_colour;
    close_all();
    if (!open_recording()) fail(where, "cannot open the recording again: " + openni_error());
    if (depth.create(device, openni::SENSOR_DEPTH) != openni::STATUS_OK ||
        (with_colour && colour.create(device, openni::SENSOR_COLOR) != openni::STATUS_OK)) {
      fail(where, "cannot open the recording's streams again: " + openni_error());
    }
    manual_playback();
    if (depth.start() != openni::STATUS_OK || (with_colour && colour.start() != openni::STATUS_OK)) {
      fail(where, "cannot start the recording's streams again: " + openni_error());
    }
  }

  // Takes one frame off whichever stream has one (bounded wait) and queues it. In the file player's manual
  // mode, waiting is what asks the player for the next recorded frame: readFrame() alone would block
  // forever, so it is only called on a stream the wait reported ready.
  void pump(const char* waiting_for) {
    openni::VideoStream* streams[] = {&depth, &colour};
    const int count = has_colour ? 2 : 1;
    int ready = -1;
    if (openni::OpenNI::waitForAnyStream(streams, count, &ready, wait_timeout_ms) != openni::STATUS_OK) {
      std::string what = std::string("no ") + waiting_for + " frame within " + std::to_string(wait_timeout_ms) + " ms";
      if (is_file) {
        what += " (frame " + std::to_string(delivered + 1) + " of " + std::to_string(total_frames) +
                "; the recording is truncated or damaged)";
      } else {
        what += " (" + openni_error() + ")";
      }
      fail(where, what);
    }
    openni::VideoFrameRef frame;
    if (streams[ready]->readFrame(&frame) != openni::STATUS_OK || !frame.isValid()) {
      fail(where, std::string("cannot read a frame: ") + openni_error());
    }
    const auto timestamp_us = static_cast<std::int64_t>(frame.getTimestamp());
    if (is_file && !accept_frame(ready, frame.getFrameIndex())) return;
    if (ready == 0) {
      depth_queue.push_back({depth_to_mm(frame, where), timestamp_us});
      ++depth_received;
    } else {
      colour_queue.push_back({colour_to_bgr(frame, where), timestamp_us});
      ++colour_received;
    }
  }

  // Files: true when `index` is the next recorded frame of stream `which` (0 depth, 1 colour); the
  // recorder numbers each stream's frames 1, 2, 3... OpenNI2's player can deliver a frame more than the
  // waits asked for when other threads wait on other OpenNI2 streams at the same time (every new frame
  // wakes every waiting thread, and a woken wait asks again), and a stream keeps only its newest frame: the
  // one before is lost. Then the recording is opened again and played up to the missing frame (seeking
  // crashed the player in stress runs). A frame missing every time is a damaged record: an Error.
  bool accept_frame(int which, int index) {
    const std::int64_t expected = (which == 0 ? depth_received : colour_received) + 1;
    if (index == expected) return true;
    if (index < expected && reopened_for_frame > 0) return false;  // catching up after reopening
    if (reopened_for_frame >= kMaxReopensPerFrame) {
      fail(where, std::string(which == 0 ? "depth" : "colour") + " frame " + std::to_string(expected) +
                      " is damaged or missing (the player went on with recorded frame " + std::to_string(index) +
                      ")");
    }
    ++reopened_for_frame;
    reopen_recording();
    return false;
  }

  // The colour frame for a depth frame taken at `timestamp_us`. Files: the recorded colour frame nearest
  // in time (each stream's recorded clock starts at 0 with its first frame). Live: the newest one.
  cv::Mat3b colour_for(std::int64_t timestamp_us) {
    if (is_file) {
      const auto colour_left = [&] { return colour_total < 0 || colour_received < colour_total; };
      while (colour_left() && (colour_queue.empty() || colour_queue.back().timestamp_us < timestamp_us)) {
        pump("colour");
      }
      const auto distance = [&](const ColourPending& c) { return std::llabs(c.timestamp_us - timestamp_us); };
      while (colour_queue.size() >= 2 && distance(colour_queue[1]) <= distance(colour_queue[0])) {
        colour_queue.pop_front();
      }
      // The chosen frame stays queued: the next depth frame may be nearer to it than to the following one.
      if (!colour_queue.empty()) last_colour = colour_queue.front().bgr;
    } else {
      while (colour_queue.empty()) pump("colour");
      last_colour = colour_queue.back().bgr;
      colour_queue.clear();
    }
    return last_colour;
  }
};

OpenNISource::OpenNISource(const std::string& spec, const FrameSourceOptions& options, int wait_timeout_ms)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.spec = spec;
  s.camera = options.camera;
  s.wait_timeout_ms = wait_timeout_ms;
  s.is_file = spec.size() > 4 && spec.compare(spec.size() - 4, 4, ".oni") == 0;
  s.where = s.is_file ? spec : (spec == "openni" ? std::string("OpenNI2 device") : "OpenNI2 device " + spec);

  // OpenNI2's initialisation changes the process's working folder while it loads its drivers: it comes
  // first, so that a relative path is never looked up meanwhile (by this source, in another thread).
  initialise_openni_once(s.where);
  if (s.is_file) {
    std::error_code ec;
    if (!std::filesystem::exists(spec, ec)) fail(spec, "no such file");
    if (!std::filesystem::is_regular_file(spec, ec)) fail(spec, "not a regular file");
    if (std::filesystem::file_size(spec, ec) < 16) fail(spec, "not an OpenNI recording (file too short)");
  }

  const bool opened = s.is_file ? s.open_recording()
                                : s.device.open(spec == "openni" ? openni::ANY_DEVICE : spec.c_str()) ==
                                      openni::STATUS_OK;
  if (!opened) {
    if (s.is_file) fail(spec, "not a readable OpenNI recording (truncated or not .oni): " + openni_error());
    if (spec == "openni") fail(s.where, "no device attached (" + openni_error() + ")");
    fail(s.where, "cannot open device (" + openni_error() + ")");
  }
  if (!s.device.hasSensor(openni::SENSOR_DEPTH)) {
    fail(s.where, s.is_file ? "recording holds no depth stream" : "has no depth stream");
  }
  if (s.depth.create(s.device, openni::SENSOR_DEPTH) != openni::STATUS_OK) {
    fail(s.where, "cannot create depth stream: " + openni_error());
  }
  if (s.device.hasSensor(openni::SENSOR_COLOR) &&
      s.colour.create(s.device, openni::SENSOR_COLOR) == openni::STATUS_OK) {
    s.has_colour = true;
  }

  if (s.is_file) {
    openni::PlaybackControl& playback = s.manual_playback();
    s.total_frames = playback.getNumberOfFrames(s.depth);
    if (s.total_frames <= 0) fail(spec, "recording holds no depth frames");
    if (!reports_cropping(s.depth)) {
      fail(spec, "recording lacks the depth stream's cropping property, so OpenNI2's file player delivers "
                 "none of its frames (recorded from a driver that does not report cropping, e.g. the Dummy "
                 "device; see docs/frames-and-openni.md)");
    }
    if (s.has_colour) {
      s.colour_total = playback.getNumberOfFrames(s.colour);
      if (s.colour_total <= 0 || !reports_cropping(s.colour)) {
        s.colour_note = s.colour_total <= 0 ? "recorded colour stream is empty"
                                            : "recorded colour stream lacks the cropping property";
        s.colour.destroy();
        s.has_colour = false;
      }
    }
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

  s.choose_camera(options);
  if (s.depth.start() != openni::STATUS_OK) fail(s.where, "cannot start depth stream: " + openni_error());
  if (s.has_colour && s.colour.start() != openni::STATUS_OK) {
    s.colour.destroy();
    s.has_colour = false;
    s.colour_note = "colour stream does not start";
  }
}

OpenNISource::~OpenNISource() = default;

bool OpenNISource::next(DepthFrame& frame) {
  Impl& s = *impl_;
  if (s.is_file && s.delivered >= s.total_frames) return false;
  while (s.depth_queue.empty()) s.pump("depth");
  DepthPending depth;
  if (s.is_file) {
    depth = std::move(s.depth_queue.front());
    s.depth_queue.pop_front();
  } else {
    depth = std::move(s.depth_queue.back());  // live: the newest frame, as a camera shows it now
    s.depth_queue.clear();
  }
  frame.depth_mm = depth.depth_mm;
  frame.bgr.release();
  if (s.has_colour) {
    cv::Mat3b bgr = s.colour_for(depth.timestamp_us);
    if (!bgr.empty() && bgr.size() != frame.depth_mm.size()) {
      cv::resize(bgr, bgr, frame.depth_mm.size(), 0, 0, cv::INTER_AREA);
    }
    frame.bgr = bgr;
  }
  s.reopened_for_frame = 0;
  frame.index = s.delivered;
  frame.name = std::to_string(s.delivered);
  frame.timestamp_us = depth.timestamp_us;
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
  text += s.has_colour ? ", depth and colour" : ", depth only";
  if (!s.colour_note.empty()) text += " (" + s.colour_note + ")";
  text += ", " + s.camera_note;
  return text;
}

std::optional<std::int64_t> OpenNISource::frame_count() const {
  if (impl_->is_file) return impl_->total_frames;
  return std::nullopt;
}

std::optional<std::vector<std::string>> OpenNISource::frame_names() const {
  if (const auto count = frame_count()) return index_frame_names(*count);
  return std::nullopt;
}

}  // namespace rdsf
