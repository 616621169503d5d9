// rdsf-record's safety (no overwrite without --force, Ctrl-C keeps a playable file, clear errors) and the
// .oni source on bad recordings: truncated, not .oni, without depth, and recordings that OpenNI2's file
// player cannot play (no cropping property, the cause of "recorded fine, plays no frames"). Every case
// ends in one line naming the file, within the wait timeout, and without a crash.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <utility>

#include "rdsf/frame/frame_source.hpp"
#include "rdsf/frame/openni_source.hpp"
#include "test_openni_fixture.hpp"

using namespace rdsf;
using namespace rdsf::test::openni;
namespace fs = std::filesystem;

namespace {

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Records `frames` frames of a fresh PNG folder into dir/name; returns the .oni path.
std::string recorded(const test::TempDir& dir, const std::string& name, int frames, const std::string& options = {},
                     const std::string& flags = {}, bool colour = false) {
  const std::string png = dir / ("png-" + name);
  fs::create_directory(png);
  write_sequence(png, frames, colour);
  const std::string oni = dir / name;
  const auto r = record("--device " + test::quote(device_uri(png, options)) + " --frames " + std::to_string(frames) +
                        " " + flags + " --out " + test::quote(oni));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return oni;
}

void drain(const std::string& spec) {
  auto source = open_frame_source(spec);
  DepthFrame frame;
  while (source->next(frame)) {
  }
}

}  // namespace

TEST(OpenNIRecorder, RefusesToOverwriteWithoutForce) {
  test::TempDir dir;
  fs::create_directory(dir / "png");
  write_sequence(dir / "png", 2, false);
  std::ofstream(dir / "take.oni") << "keep me";
  const std::string args = "--device " + test::quote(device_uri(dir / "png")) + " --frames 2 --out " +
                           test::quote(dir / "take.oni");
  const auto refused = record(args);
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("take.oni: already exists (pass --force"), std::string::npos) << refused.err;
  EXPECT_EQ(file_text(dir / "take.oni"), "keep me");
  const auto forced = record(args + " --force");
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_EQ(open_frame_source(dir / "take.oni")->frame_count().value_or(-1), 2);
}

TEST(OpenNIRecorder, CtrlCStopsAndKeepsAPlayableFile) {
  test::TempDir dir;
  fs::create_directory(dir / "png");
  constexpr int kPngs = 40;
  write_sequence(dir / "png", kPngs, false);
  // 10 frames per second: the whole folder would take 4 s; SIGINT comes after about 1.5 s.
  // (A shell without job control starts background programs with SIGINT ignored: rdsf-record installs its
  // own handler, so this also checks that.)
  const auto r = test::run("{ " + test::quote(test::program("rdsf-record")) + " --device " +
                           test::quote(device_uri(dir / "png", "fps=10")) + " --out " + test::quote(dir / "take.oni") +
                           " & pid=$!; sleep 1.5; kill -INT $pid; wait $pid; }");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("stopped by Ctrl-C"), std::string::npos) << r.err;
  auto source = open_frame_source(dir / "take.oni");
  const std::int64_t frames = source->frame_count().value_or(-1);
  EXPECT_GE(frames, 1);
  EXPECT_LT(frames, kPngs);
  DepthFrame frame;
  int read = 0;
  while (source->next(frame)) {
    EXPECT_TRUE(identical(frame.depth_mm, depth_for(read))) << "frame " << read;
    ++read;
  }
  EXPECT_EQ(read, frames);
}

TEST(OpenNIRecorder, CtrlCBeforeTheFirstFrameWritesNothing) {
  test::TempDir dir;
  fs::create_directory(dir / "png");
  write_sequence(dir / "png", 2, false);
  // One frame per second: SIGINT as soon as the recorder says it is recording comes before the first frame.
  // (A fixed sleep instead raced the program's start on a loaded machine: SIGINT before its handler.)
  const std::string err = dir / "err.txt";
  const auto r = test::run("{ " + test::quote(test::program("rdsf-record")) + " --device " +
                           test::quote(device_uri(dir / "png", "fps=1")) + " --out " + test::quote(dir / "take.oni") +
                           " 2>" + test::quote(err) + " & pid=$!; for i in $(seq 1500); do grep -q 'rdsf-record: recording' " +
                           test::quote(err) + " && break; sleep 0.02; done; kill -INT $pid; wait $pid; rc=$?; cat " +
                           test::quote(err) + " >&2; exit $rc; }");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("stopped before the first frame; nothing written"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "take.oni"));
  EXPECT_FALSE(fs::exists(dir / "take.oni.part"));
}

TEST(OpenNIRecorder, DeviceThatStopsEarlyLeavesWhatWasRecorded) {
  test::TempDir dir;
  fs::create_directory(dir / "png");
  write_sequence(dir / "png", 3, false);
  const auto r = record("--device " + test::quote(device_uri(dir / "png")) + " --frames 10 --timeout-ms 500 --out " +
                        test::quote(dir / "take.oni"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("no frame within 500 ms"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("holds the 3 depth frames"), std::string::npos) << r.err;
  EXPECT_EQ(open_frame_source(dir / "take.oni")->frame_count().value_or(-1), 3);
}

TEST(OpenNIRecorder, BadDeviceAndOptionsAreOneLineErrors) {
  test::TempDir dir;
  const auto missing = record("--device rdsf-png:///no/such/folder --frames 1 --out " + test::quote(dir / "a.oni"));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("/no/such/folder: no such folder"), std::string::npos) << missing.err;
  const auto name = record("--device rdsf-png:///x --out " + test::quote(dir / "a.avi"));
  EXPECT_EQ(name.exit_code, 1);
  EXPECT_NE(name.err.find("must end in .oni"), std::string::npos) << name.err;
  fs::create_directory(dir / "png");
  write_sequence(dir / "png", 1, false);
  const auto no_colour = record("--device " + test::quote(device_uri(dir / "png")) + " --color --out " +
                                test::quote(dir / "a.oni"));
  EXPECT_EQ(no_colour.exit_code, 1);
  EXPECT_NE(no_colour.err.find("has no colour stream"), std::string::npos) << no_colour.err;
  EXPECT_FALSE(fs::exists(dir / "a.oni"));
  EXPECT_EQ(record("--frames -1 --out " + test::quote(dir / "a.oni")).exit_code, 2);
}

TEST(OpenNIBadRecording, TruncatedRecordingIsAnErrorNotAHang) {
  test::TempDir dir;
  const std::string whole = recorded(dir, "whole.oni", 6);
  const std::string bytes = file_text(whole);
  const std::string cut = dir / "cut.oni";
  // A quarter: the header and the first frames stay, the later frames are cut off.
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 4);
  // Either the player refuses the file, or it plays what is there and the first missing frame is an error.
  std::string message;
  int frames = 0;
  try {
    OpenNISource source(cut, FrameSourceOptions{}, 1000);
    DepthFrame frame;
    while (source.next(frame)) {
      EXPECT_TRUE(identical(frame.depth_mm, depth_for(frames))) << "frame " << frames;
      ++frames;
    }
  } catch (const Error& e) {
    message = e.what();
  }
  ASSERT_FALSE(message.empty()) << "a quarter of the file read as complete (" << frames << " frames)";
  std::cout << "  truncated recording: " << frames << " frames, then: " << message << "\n";
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_NE(message.find("cut.oni"), std::string::npos) << message;
  EXPECT_LT(frames, 6);
}

// Where the third frame's record starts: records begin with "NIR\0" and their type (10: a frame).
std::size_t third_frame_record(const std::string& bytes) {
  std::size_t at = 0;
  for (int frame_records = 0; frame_records < 3;) {
    at = bytes.find(std::string("NIR\0", 4), at + 1);
    if (at == std::string::npos) return at;
    if (bytes[at + 4] == 10) ++frame_records;
  }
  return at;
}

// Plays `path` with 500 ms waits; returns the frames read and the error.
std::pair<int, std::string> play(const std::string& path) {
  int frames = 0;
  try {
    OpenNISource source(path, FrameSourceOptions{}, 500);
    DepthFrame frame;
    while (source.next(frame)) {
      EXPECT_TRUE(identical(frame.depth_mm, depth_for(frames))) << "frame " << frames;
      ++frames;
    }
  } catch (const Error& e) {
    return {frames, e.what()};
  }
  return {frames, ""};
}

TEST(OpenNIBadRecording, DamagedFrameRecordIsAnErrorNotAHang) {
  test::TempDir dir;
  const std::string bytes = file_text(recorded(dir, "whole.oni", 5));
  const std::size_t at = third_frame_record(bytes);
  ASSERT_NE(at, std::string::npos) << "fewer than 3 frame records";
  // A spoilt record type: the player stops there; the wait for frame 3 times out.
  std::string spoilt_type = bytes;
  spoilt_type[at + 4] = 99;
  std::ofstream(dir / "type.oni", std::ios::binary) << spoilt_type;
  const auto [type_frames, type_error] = play(dir / "type.oni");
  EXPECT_EQ(type_frames, 2) << "the frames before the damage play";
  EXPECT_NE(type_error.find("type.oni: no depth frame within 500 ms (frame 3 of 5"), std::string::npos) << type_error;
  // Spoilt frame data: the player skips the frame and goes on with frame 4. The source notices by the
  // frame numbers, opens the recording again to find frame 3, and after a few tries reports it.
  std::string spoilt_data = bytes;
  // Record header: "NIR\0", type, node, header size, payload size (little-endian 32-bit each), ...
  const auto field = [&](std::size_t offset) {
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i) value = value * 256 + static_cast<unsigned char>(bytes[at + offset + i]);
    return static_cast<std::size_t>(value);
  };
  const std::size_t header_size = field(12);
  const std::size_t payload_size = field(16);
  ASSERT_LE(at + header_size + payload_size, bytes.size());
  std::fill(spoilt_data.begin() + static_cast<std::ptrdiff_t>(at + header_size),
            spoilt_data.begin() + static_cast<std::ptrdiff_t>(at + header_size + payload_size), '\xff');
  std::ofstream(dir / "data.oni", std::ios::binary) << spoilt_data;
  const auto [data_frames, data_error] = play(dir / "data.oni");
  EXPECT_EQ(data_frames, 2);
  EXPECT_NE(data_error.find("data.oni: depth frame 3 is damaged or missing (the player went on with recorded frame 4)"),
            std::string::npos)
      << data_error;
}

TEST(OpenNIBadRecording, PngRenamedToOniIsRefused) {
  test::TempDir dir;
  write_png_atomically(dir / "frame.depth.png", depth_for(0));
  fs::copy_file(dir / "frame.depth.png", dir / "frame.oni");
  expect_error([&] { drain(dir / "frame.oni"); }, {"frame.oni", "not a readable OpenNI recording"});
}

TEST(OpenNIBadRecording, RecordingWithoutDepthIsRefused) {
  test::TempDir dir;
  const std::string oni = recorded(dir, "colour.oni", 3, "depth=off", "--color --no-depth", true);
  expect_error([&] { drain(oni); }, {"colour.oni", "recording holds no depth stream"});
}

TEST(OpenNIBadRecording, RecordingWithoutCroppingPropertyIsExplained) {
  // As recorded from OpenNI2's Dummy device: OpenNI2's player drops every frame of such a file.
  test::TempDir dir;
  const std::string oni = recorded(dir, "nocrop.oni", 3, "crop=off");
  expect_error([&] { drain(oni); }, {"nocrop.oni", "cropping property", "none of its frames"});
}

TEST(OpenNIBadRecording, BadVirtualSensorAddressesAreOneLineErrors) {
  test::TempDir dir;
  expect_error([&] { drain(device_uri(dir / "absent")); }, {"absent: no such folder"});
  expect_error([&] { drain(device_uri(dir.path().string())); }, {"no NAME.depth.png"});
  write_sequence(dir.path().string(), 1, false);
  expect_error([&] { drain(device_uri(dir.path().string(), "fps=0")); }, {"unknown option 'fps=0'"});
  expect_error([&] { drain(device_uri(dir.path().string(), "hfov=180")); }, {"unknown option 'hfov=180'"});
  expect_error([&] { drain(device_uri(dir.path().string(), "hfov=60x")); }, {"unknown option 'hfov=60x'"});
}
