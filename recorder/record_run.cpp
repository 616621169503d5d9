#include "recorder/record_run.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <OpenNI.h>

#include "cli/cli.hpp"
#include "cli/progress.hpp"
#include "rdsf/core/durable_io.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/frame/openni_source.hpp"
#include "recorder/stop_request.hpp"

namespace rdsf::recorder {
namespace {

std::string openni_error() { return openni_last_error(); }

// Picks the 640x480 mode of `format` when the sensor offers it (a Kinect's default may be 320x240).
void prefer_vga(openni::VideoStream& stream, openni::PixelFormat format) {
  const auto& modes = stream.getSensorInfo().getSupportedVideoModes();
  for (int i = 0; i < modes.getSize(); ++i) {
    if (modes[i].getPixelFormat() == format && modes[i].getResolutionX() == 640 &&
        modes[i].getResolutionY() == 480) {
      stream.setVideoMode(modes[i]);
      return;
    }
  }
}

std::string mode_text(const openni::VideoStream& stream) {
  const openni::VideoMode mode = stream.getVideoMode();
  return std::to_string(mode.getResolutionX()) + "x" + std::to_string(mode.getResolutionY()) + " at " +
         std::to_string(mode.getFps()) + " fps";
}

// Everything OpenNI2 holds for one recording, released in the order that keeps the file whole: the
// recorder finishes the file (seek table, frame counts) before the streams and the device go.
struct Session {
  openni::Device device;
  openni::VideoStream depth;
  openni::VideoStream colour;
  openni::Recorder recorder;
  bool recording = false;
  std::string partial;        // the file being written; removed when the recording never got going
  bool keep_partial = false;

  void finish() {
    if (recording) recorder.stop();
    recording = false;
    if (depth.isValid()) depth.stop();
    if (colour.isValid()) colour.stop();
    if (recorder.isValid()) recorder.destroy();
    if (depth.isValid()) depth.destroy();
    if (colour.isValid()) colour.destroy();
    if (device.isValid()) device.close();
  }
  ~Session() {
    finish();
    std::error_code ec;
    if (!partial.empty() && !keep_partial) std::filesystem::remove(partial, ec);
  }
};

/// The streams to record, in order (depth first), with their names for the messages.
struct Streams {
  std::vector<openni::VideoStream*> streams;
  std::vector<const char*> names;
};

/// Refuses to replace --out without --force, and a --out in a folder that does not exist.
void check_output(const RecordOptions& o) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(o.out, ec) && !o.force) throw Error(o.out + ": already exists (pass --force to replace it)");
  const fs::path parent = fs::path(o.out).parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec)) throw Error(o.out + ": no such folder " + parent.string());
}

/// Creates one stream of `sensor` at 640x480 when offered.
void create_stream(Session& s, const std::string& where, openni::SensorType sensor, openni::VideoStream& stream,
                   openni::PixelFormat format, const std::string& name, const std::string& missing) {
  if (!s.device.hasSensor(sensor)) throw Error(where + ": has no " + name + " stream" + missing);
  if (stream.create(s.device, sensor) != openni::STATUS_OK) {
    throw Error(where + ": cannot create the " + name + " stream: " + openni_error());
  }
  prefer_vga(stream, format);
}

/// Opens the device and creates the streams --depth and --colour ask for.
Streams open_device(Session& s, const RecordOptions& o, const std::string& where) {
  if (s.device.open(o.device == "openni" ? openni::ANY_DEVICE : o.device.c_str()) != openni::STATUS_OK) {
    throw Error(where + ": " + (o.device == "openni" ? "no device attached (" : "cannot open device (") +
                openni_error() + ")");
  }
  Streams out;
  if (o.depth) {
    create_stream(s, where, openni::SENSOR_DEPTH, s.depth, openni::PIXEL_FORMAT_DEPTH_1_MM, "depth", "");
    out.streams.push_back(&s.depth);
    out.names.push_back("depth");
  }
  if (o.colour) {
    create_stream(s, where, openni::SENSOR_COLOR, s.colour, openni::PIXEL_FORMAT_RGB888, "colour", " (drop --colour)");
    out.streams.push_back(&s.colour);
    out.names.push_back("colour");
    if (o.depth) {
      // Colour pixel for pixel with depth, and frames in pairs, when the device can.
      if (s.device.isImageRegistrationModeSupported(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR)) {
        s.device.setImageRegistrationMode(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR);
      }
      s.device.setDepthColorSyncEnabled(true);
    }
  }
  return out;
}

/// Starts the recorder on `partial`, then the streams, so the first frame is in the file.
void start_recording(Session& s, const Streams& streams, const std::string& partial, const std::string& where) {
  std::error_code ec;
  std::filesystem::remove(partial, ec);  // left over from a recording killed hard
  s.partial = partial;
  if (s.recorder.create(partial.c_str()) != openni::STATUS_OK) {
    throw Error(partial + ": cannot create the recording: " + openni_error());
  }
  for (openni::VideoStream* stream : streams.streams) {
    // Lossless: the recording keeps every depth millimetre and colour byte as the device sent them.
    if (s.recorder.attach(*stream, false) != openni::STATUS_OK) {
      throw Error(partial + ": cannot attach a stream to the recorder: " + openni_error());
    }
  }
  if (s.recorder.start() != openni::STATUS_OK) throw Error(partial + ": cannot start recording: " + openni_error());
  s.recording = true;
  for (std::size_t i = 0; i < streams.streams.size(); ++i) {
    if (streams.streams[i]->start() != openni::STATUS_OK) {
      throw Error(where + ": cannot start the " + streams.names[i] + " stream: " + openni_error());
    }
  }
}

/// Per stream the frames recorded, and why the device counts as gone (empty: it did not).
struct Recorded {
  std::vector<std::int64_t> counts;
  std::string device_gone;
};

/// Reads frames until every stream has --frames, Ctrl-C, or no frame comes within --timeout-ms.
Recorded record_frames(const RecordOptions& o, const Streams& streams, const std::string& where, cli::Progress& progress) {
  Recorded r;
  r.counts.assign(streams.streams.size(), 0);
  std::vector<std::int64_t> first_index(streams.streams.size(), -1);
  const auto all_done = [&] {
    if (o.frames <= 0) return false;
    for (std::int64_t c : r.counts) {
      if (c < o.frames) return false;
    }
    return true;
  };
  auto last_frame = std::chrono::steady_clock::now();
  constexpr int kSliceMs = 100;  // short waits, so Ctrl-C is answered at once
  while (!stop_requested() && !all_done()) {
    // Streams that have all their frames are not waited on: their next frames are not wanted.
    std::vector<openni::VideoStream*> waiting;
    std::vector<std::size_t> which;
    for (std::size_t i = 0; i < streams.streams.size(); ++i) {
      if (o.frames <= 0 || r.counts[i] < o.frames) {
        waiting.push_back(streams.streams[i]);
        which.push_back(i);
      }
    }
    int ready = -1;
    const openni::Status status =
        openni::OpenNI::waitForAnyStream(waiting.data(), static_cast<int>(waiting.size()), &ready, kSliceMs);
    if (status != openni::STATUS_OK) {
      const auto quiet_ms = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() -
                                                                                 last_frame).count();
      if (quiet_ms >= o.timeout_ms) {
        r.device_gone = where + ": no frame within " + std::to_string(o.timeout_ms) + " ms (device stopped sending)";
        break;
      }
      continue;
    }
    openni::VideoFrameRef frame;
    if (waiting[static_cast<std::size_t>(ready)]->readFrame(&frame) != openni::STATUS_OK || !frame.isValid()) continue;
    last_frame = std::chrono::steady_clock::now();
    // Counted by the device's frame index: a stream keeps only its newest frame, so when frames come
    // faster than this loop reads them (a busy machine), some are never read here, although the recorder
    // stored them all. OpenNI2 drivers number a stream's frames from 1 when it starts (the virtual sensor,
    // PS1080, and the file player do), and the recorder runs from before the start: a first index read of
    // 2..5 means the first frames came too fast to read, not that they are missing from the file.
    const std::size_t k = which[static_cast<std::size_t>(ready)];
    if (first_index[k] < 0) {
      const int index = frame.getFrameIndex();
      first_index[k] = (index >= 1 && index <= 5) ? 1 : index;
    }
    r.counts[k] = std::max<std::int64_t>(r.counts[k], frame.getFrameIndex() - first_index[k] + 1);
    progress.update(r.counts[0]);
  }
  return r;
}

}  // namespace

void check_options(const RecordOptions& o) {
  if (o.frames < 0) throw cli::UsageError("--frames must be 0 or more");
  if (o.timeout_ms < 1) throw cli::UsageError("--timeout-ms must be at least 1");
  if (o.out.size() <= 4 || o.out.compare(o.out.size() - 4, 4, ".oni") != 0) {
    throw Error(o.out + ": the recording's name must end in .oni (the workbench knows recordings by it)");
  }
  if (!o.depth && !o.colour) throw cli::UsageError("nothing to record: --no-depth needs --colour");
}

int run_record(const RecordOptions& o) {
  check_output(o);
  const std::string partial = o.out + ".part";
  const std::string where = o.device == "openni" ? std::string("OpenNI2 device") : "OpenNI2 device " + o.device;

  // From here on Ctrl-C is a request: during the setup it means "stop before the first frame".
  install_stop_request_handlers();
  if (openni::OpenNI::initialize() != openni::STATUS_OK) {
    throw Error(where + ": OpenNI2 cannot be initialised: " + openni_error());
  }
  Session s;
  const Streams streams = open_device(s, o, where);
  start_recording(s, streams, partial, where);
  std::cerr << "rdsf-record: recording " << (o.depth ? "depth " + mode_text(s.depth) : std::string())
            << (o.depth && o.colour ? " and " : "") << (o.colour ? "colour " + mode_text(s.colour) : std::string())
            << " from " << where << " to " << o.out << (o.frames > 0 ? "" : " (Ctrl-C stops)") << "\n";

  cli::Progress progress(std::cerr, "frames", o.frames > 0 ? std::optional<std::int64_t>(o.frames) : std::nullopt);
  const Recorded r = record_frames(o, streams, where, progress);
  // Finish the file first (the recorder writes its frame table on stop), then make it visible.
  const bool any_frame = std::any_of(r.counts.begin(), r.counts.end(), [](std::int64_t c) { return c > 0; });
  s.keep_partial = any_frame;  // a recording without frames is not playable: not kept
  s.finish();
  if (!any_frame) {
    throw Error((r.device_gone.empty() ? where + ": stopped" : r.device_gone) + " before the first frame; nothing written");
  }
  progress.finish(r.counts[0], stop_requested() ? "stopped by Ctrl-C" : std::string());
  rename_durably(partial, o.out);  // synced, renamed, folder synced (core/durable_io)
  std::string summary = std::to_string(r.counts[0]) + " " + streams.names[0] + " frames";
  if (r.counts.size() > 1) summary += " and " + std::to_string(r.counts[1]) + " " + streams.names[1] + " frames";
  if (!r.device_gone.empty()) throw Error(r.device_gone + "; " + o.out + " holds the " + summary + " recorded before");
  std::cout << "rdsf-record: wrote " << summary << " to " << o.out << "\n";
  return 0;
}

}  // namespace rdsf::recorder
