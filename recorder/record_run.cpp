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

}  // namespace

int run_record(const RecordOptions& o) {
  namespace fs = std::filesystem;
  if (o.out.size() <= 4 || o.out.compare(o.out.size() - 4, 4, ".oni") != 0) {
    throw Error(o.out + ": the recording's name must end in .oni (the workbench knows recordings by it)");
  }
  if (!o.depth && !o.colour) throw cli::UsageError("nothing to record: --no-depth needs --colour");
  std::error_code ec;
  if (fs::exists(o.out, ec) && !o.force) throw Error(o.out + ": already exists (pass --force to replace it)");
  const fs::path parent = fs::path(o.out).parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec)) throw Error(o.out + ": no such folder " + parent.string());
  const std::string partial = o.out + ".part";
  const std::string where = o.device == "openni" ? std::string("OpenNI2 device") : "OpenNI2 device " + o.device;

  // From here on Ctrl-C is a request: during the setup it means "stop before the first frame".
  install_stop_request_handlers();
  if (openni::OpenNI::initialize() != openni::STATUS_OK) {
    throw Error(where + ": OpenNI2 cannot be initialised: " + openni_error());
  }
  Session s;
  if (s.device.open(o.device == "openni" ? openni::ANY_DEVICE : o.device.c_str()) != openni::STATUS_OK) {
    throw Error(where + ": " + (o.device == "openni" ? "no device attached (" : "cannot open device (") +
                openni_error() + ")");
  }
  std::vector<openni::VideoStream*> streams;
  std::vector<const char*> names;
  if (o.depth) {
    if (!s.device.hasSensor(openni::SENSOR_DEPTH)) throw Error(where + ": has no depth stream");
    if (s.depth.create(s.device, openni::SENSOR_DEPTH) != openni::STATUS_OK) {
      throw Error(where + ": cannot create the depth stream: " + openni_error());
    }
    prefer_vga(s.depth, openni::PIXEL_FORMAT_DEPTH_1_MM);
    streams.push_back(&s.depth);
    names.push_back("depth");
  }
  if (o.colour) {
    if (!s.device.hasSensor(openni::SENSOR_COLOR)) throw Error(where + ": has no colour stream (drop --colour)");
    if (s.colour.create(s.device, openni::SENSOR_COLOR) != openni::STATUS_OK) {
      throw Error(where + ": cannot create the colour stream: " + openni_error());
    }
    prefer_vga(s.colour, openni::PIXEL_FORMAT_RGB888);
    streams.push_back(&s.colour);
    names.push_back("colour");
    if (o.depth) {
      // Colour pixel for pixel with depth, and frames in pairs, when the device can.
      if (s.device.isImageRegistrationModeSupported(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR)) {
        s.device.setImageRegistrationMode(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR);
      }
      s.device.setDepthColorSyncEnabled(true);
    }
  }

  fs::remove(partial, ec);  // left over from a recording killed hard
  s.partial = partial;
  if (s.recorder.create(partial.c_str()) != openni::STATUS_OK) {
    throw Error(partial + ": cannot create the recording: " + openni_error());
  }
  for (openni::VideoStream* stream : streams) {
    // Lossless: the recording keeps every depth millimetre and colour byte as the device sent them.
    if (s.recorder.attach(*stream, false) != openni::STATUS_OK) {
      throw Error(partial + ": cannot attach a stream to the recorder: " + openni_error());
    }
  }
  // The recorder runs before the streams start, so the first frame is in the file.
  if (s.recorder.start() != openni::STATUS_OK) throw Error(partial + ": cannot start recording: " + openni_error());
  s.recording = true;
  for (std::size_t i = 0; i < streams.size(); ++i) {
    if (streams[i]->start() != openni::STATUS_OK) {
      throw Error(where + ": cannot start the " + names[i] + " stream: " + openni_error());
    }
  }
  std::cerr << "rdsf-record: recording " << (o.depth ? "depth " + mode_text(s.depth) : std::string())
            << (o.depth && o.colour ? " and " : "") << (o.colour ? "colour " + mode_text(s.colour) : std::string())
            << " from " << where << " to " << o.out << (o.frames > 0 ? "" : " (Ctrl-C stops)") << "\n";

  cli::Progress progress(std::cerr, "frames", o.frames > 0 ? std::optional<std::int64_t>(o.frames) : std::nullopt);
  std::vector<std::int64_t> counts(streams.size(), 0);
  std::vector<std::int64_t> first_index(streams.size(), -1);
  const auto all_done = [&] {
    if (o.frames <= 0) return false;
    for (std::int64_t c : counts) {
      if (c < o.frames) return false;
    }
    return true;
  };
  std::string device_gone;
  auto last_frame = std::chrono::steady_clock::now();
  constexpr int kSliceMs = 100;  // short waits, so Ctrl-C is answered at once
  while (!stop_requested() && !all_done()) {
    // Streams that have all their frames are not waited on: their next frames are not wanted.
    std::vector<openni::VideoStream*> waiting;
    std::vector<std::size_t> which;
    for (std::size_t i = 0; i < streams.size(); ++i) {
      if (o.frames <= 0 || counts[i] < o.frames) {
        waiting.push_back(streams[i]);
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
        device_gone = where + ": no frame within " + std::to_string(o.timeout_ms) + " ms (device stopped sending)";
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
    counts[k] = std::max<std::int64_t>(counts[k], frame.getFrameIndex() - first_index[k] + 1);
    progress.update(counts[0]);
  }
  // Finish the file first (the recorder writes its frame table on stop), then make it visible.
  const bool any_frame = std::any_of(counts.begin(), counts.end(), [](std::int64_t c) { return c > 0; });
  s.keep_partial = any_frame;  // a recording without frames is not playable: not kept
  s.finish();
  if (!any_frame) {
    throw Error((device_gone.empty() ? where + ": stopped" : device_gone) + " before the first frame; nothing written");
  }
  progress.finish(counts[0], stop_requested() ? "stopped by Ctrl-C" : std::string());
  rename_durably(partial, o.out);  // synced, renamed, folder synced (core/durable_io)
  std::string summary = std::to_string(counts[0]) + " " + names[0] + " frames";
  if (counts.size() > 1) summary += " and " + std::to_string(counts[1]) + " " + names[1] + " frames";
  if (!device_gone.empty()) throw Error(device_gone + "; " + o.out + " holds the " + summary + " recorded before");
  std::cout << "rdsf-record: wrote " << summary << " to " << o.out << "\n";
  return 0;
}

}  // namespace rdsf::recorder
