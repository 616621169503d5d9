// PNG folder -> virtual sensor (rdsf-png://, the project's OpenNI2 driver) -> rdsf-record (OpenNI2's own
// recorder) -> .oni -> OpenNI2's file player (OniFile) through open_frame_source: every frame once, in
// order, with its index, timestamp and exact depth and colour values. No Kinect needed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "rdsf/frame/frame_source.hpp"
#include "test_openni_fixture.hpp"

using namespace rdsf;
using namespace rdsf::test::openni;
namespace fs = std::filesystem;

namespace {

constexpr int kFrames = 6;
// The virtual sensor's clock: frame i at i/30 s, in whole microseconds (OpenNI2's recorder keeps it).
std::int64_t timestamp_us(int i) { return static_cast<std::int64_t>(i) * 1000000 / 30; }

// Reads the whole recording and checks it against the PNG sequence.
void expect_recording_matches(const std::string& oni, int frames, bool colour) {
  auto source = open_frame_source(oni);
  ASSERT_TRUE(source->frame_count().has_value());
  EXPECT_EQ(*source->frame_count(), frames);
  EXPECT_NE(source->description().find(colour ? "depth and colour" : "depth only"), std::string::npos)
      << source->description();
  DepthFrame frame;
  int read = 0;
  while (source->next(frame)) {
    ASSERT_LT(read, frames) << "more frames than recorded";
    EXPECT_EQ(frame.index, read);
    EXPECT_EQ(frame.name, std::to_string(read));
    EXPECT_EQ(frame.timestamp_us, timestamp_us(read)) << "frame " << read;
    EXPECT_TRUE(identical(frame.depth_mm, depth_for(read))) << "depth of frame " << read << " differs";
    EXPECT_EQ(frame.camera, CameraModel::kinect_v1());
    if (colour) {
      ASSERT_TRUE(frame.has_colour()) << "frame " << read;
      EXPECT_TRUE(identical(frame.bgr, colour_for(read))) << "colour of frame " << read << " differs";
    } else {
      EXPECT_FALSE(frame.has_colour());
    }
    ++read;
  }
  EXPECT_EQ(read, frames);
  EXPECT_FALSE(source->next(frame)) << "the end stays the end";
}

}  // namespace

TEST(OpenNIRoundTrip, DepthOnlyFramesComeBackExactly) {
  test::TempDir dir;
  fs::create_directory(dir / "png");
  write_sequence(dir / "png", kFrames, false);
  const auto r = record("--device " + test::quote(device_uri(dir / "png")) + " --frames " +
                        std::to_string(kFrames) + " --out " + test::quote(dir / "take.oni"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote 6 depth frames"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "take.oni.part")) << "the temporary name is gone";
  expect_recording_matches(dir / "take.oni", kFrames, false);
}

TEST(OpenNIRoundTrip, DepthAndColourFramesComeBackExactly) {
  test::TempDir dir;
  fs::create_directory(dir / "png");
  write_sequence(dir / "png", kFrames, true);
  const auto r = record("--device " + test::quote(device_uri(dir / "png")) + " --frames " +
                        std::to_string(kFrames) + " --color --out " + test::quote(dir / "take.oni"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("6 depth frames and 6 colour frames"), std::string::npos) << r.out;
  expect_recording_matches(dir / "take.oni", kFrames, true);
}

TEST(OpenNIRoundTrip, RealKinectFramesComeBackExactly) {
  RDSF_REQUIRE_REALDATA();
  const fs::path people = test::realdata_dir() / "people";
  std::vector<std::string> pngs;
  for (const auto& entry : fs::directory_iterator(people)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 10 && name.compare(name.size() - 10, 10, ".depth.png") == 0) pngs.push_back(entry.path());
  }
  std::sort(pngs.begin(), pngs.end());
  ASSERT_FALSE(pngs.empty());
  test::TempDir dir;
  const auto r = record("--device " + test::quote(device_uri(people.string(), "fps=100")) + " --frames " +
                        std::to_string(pngs.size()) + " --out " + test::quote(dir / "people.oni"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto source = open_frame_source(dir / "people.oni");
  EXPECT_EQ(source->frame_count().value_or(-1), static_cast<std::int64_t>(pngs.size()));
  DepthFrame frame;
  std::size_t read = 0;
  while (source->next(frame)) {
    ASSERT_LT(read, pngs.size());
    EXPECT_TRUE(identical(frame.depth_mm, read_depth_png(pngs[read]))) << pngs[read];
    ++read;
  }
  EXPECT_EQ(read, pngs.size());
}

TEST(OpenNIRoundTrip, TwoSourcesOnOneRecordingReadIndependently) {
  test::TempDir dir;
  fs::create_directory(dir / "png");
  write_sequence(dir / "png", 3, false);
  ASSERT_EQ(record("--device " + test::quote(device_uri(dir / "png")) + " --frames 3 --out " +
                   test::quote(dir / "take.oni")).exit_code, 0);
  // Reopening plays from the start again. Two sources open at once on one file are independent (OpenNI2
  // would share one player between them: each would lose frames to the other).
  expect_recording_matches(dir / "take.oni", 3, false);
  auto first = open_frame_source(dir / "take.oni");
  auto second = open_frame_source(dir / "take.oni");
  DepthFrame a;
  DepthFrame b;
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(first->next(a));
    ASSERT_TRUE(second->next(b));
    EXPECT_EQ(a.index, i);
    EXPECT_EQ(b.index, i);
    EXPECT_TRUE(identical(a.depth_mm, b.depth_mm));
  }
  EXPECT_FALSE(first->next(a));
  EXPECT_FALSE(second->next(b));
  // One read to the end while the other waits, then the other from its start.
  auto third = open_frame_source(dir / "take.oni");
  auto fourth = open_frame_source(dir / "take.oni");
  for (auto* source : {third.get(), fourth.get()}) {
    int read = 0;
    while (source->next(a)) {
      EXPECT_EQ(a.index, read);
      EXPECT_TRUE(identical(a.depth_mm, depth_for(read))) << "frame " << read;
      ++read;
    }
    EXPECT_EQ(read, 3);
  }
}

TEST(OpenNIRoundTrip, ReadersInParallelThreadsGetEveryFrame) {
  // OpenNI2 wakes every waiting thread on every new frame, which can make its player send a frame more
  // than asked for; the source notices by the frame numbers and replays (docs/frames-and-openni.md, "What was wrong").
  test::TempDir dir;
  fs::create_directory(dir / "png");
  write_sequence(dir / "png", 8, true);
  ASSERT_EQ(record("--device " + test::quote(device_uri(dir / "png", "fps=100")) + " --frames 8 --color --out " +
                   test::quote(dir / "take.oni")).exit_code, 0);
  std::vector<std::string> problems(4);
  std::vector<std::thread> readers;
  for (std::size_t t = 0; t < problems.size(); ++t) {
    readers.emplace_back([&, t] {
      try {
        auto source = open_frame_source(dir / "take.oni");
        DepthFrame frame;
        int read = 0;
        while (source->next(frame)) {
          if (frame.index != read || !identical(frame.depth_mm, depth_for(read)) ||
              !identical(frame.bgr, colour_for(read))) {
            problems[t] += "frame " + std::to_string(read) + " differs; ";
          }
          ++read;
        }
        if (read != 8) problems[t] += std::to_string(read) + " frames read";
      } catch (const std::exception& e) {
        problems[t] = e.what();
      }
    });
  }
  for (auto& reader : readers) reader.join();
  for (const std::string& problem : problems) EXPECT_EQ(problem, "");
}

TEST(OpenNIRoundTrip, LiveVirtualSensorServesThePngs) {
  test::TempDir dir;
  write_sequence(dir.path().string(), 4, true);
  auto source = open_frame_source(device_uri(dir.path().string()));
  EXPECT_FALSE(source->frame_count().has_value()) << "a live device has no known length";
  DepthFrame frame;
  int last = -1;
  for (int n = 0; n < 2; ++n) {
    ASSERT_TRUE(source->next(frame));
    // A live source shows the newest frame: which PNG it is depends on timing, but it is one of them,
    // whole, with its own colour, and later than the one before.
    int match = -1;
    for (int i = 0; i < 4; ++i) {
      if (identical(frame.depth_mm, depth_for(i))) match = i;
    }
    ASSERT_GE(match, 0) << "depth equals none of the PNGs";
    EXPECT_GT(match, last);
    ASSERT_TRUE(frame.has_colour());
    EXPECT_TRUE(identical(frame.bgr, colour_for(match)));
    last = match;
  }
}

// A sensor of another size and field of view (a Kinect v2's depth: 512x424, 70.6 degrees wide): its frames,
// live and recorded, carry the model of that field of view without any option; a model the user gives wins.
TEST(OpenNIRoundTrip, CameraModelComesFromTheFieldOfViewTheSensorReports) {
  test::TempDir dir;
  for (const bool colour : {false, true}) {
    const fs::path png = dir / (colour ? "colour" : "depth");
    fs::create_directory(png);
    write_sequence(png.string(), 3, colour, {512, 424});
    const double focal_px = 256.0 / std::tan(70.6 / 2.0 * M_PI / 180.0);  // 361.6 px
    const auto expect_kinect_v2 = [&](const DepthFrame& frame, const std::string& where) {
      EXPECT_EQ(frame.camera.width_px, 512) << where;
      EXPECT_EQ(frame.camera.height_px, 424) << where;
      EXPECT_NEAR(frame.camera.fx_px, focal_px, 0.01) << where;
      EXPECT_EQ(frame.camera.fy_px, frame.camera.fx_px) << where;
      EXPECT_EQ(frame.camera.cx_px, 255.5) << where;
      EXPECT_EQ(frame.camera.cy_px, 211.5) << where;
    };
    const std::string uri = device_uri(png.string(), "hfov=70.6");
    DepthFrame frame;
    {
      auto live = open_frame_source(uri);
      ASSERT_TRUE(live->next(frame));
      expect_kinect_v2(frame, "live");
      const std::string stream = colour ? "colour stream (depth registered to colour)" : "depth stream";
      EXPECT_NE(live->description().find("camera model from OpenNI2's field of view of the " + stream),
                std::string::npos) << live->description();
    }
    const fs::path oni = dir / (colour ? "colour.oni" : "depth.oni");
    const auto r = record("--device " + test::quote(uri) + " --frames 3" + (colour ? " --color" : "") + " --out " +
                          test::quote(oni));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto recorded = open_frame_source(oni.string());
    ASSERT_TRUE(recorded->next(frame));
    expect_kinect_v2(frame, "recorded");

    FrameSourceOptions given;
    given.camera_given = true;  // e.g. --fx on the command line: the user's model, scaled to the frame
    auto with_model = open_frame_source(oni.string(), given);
    ASSERT_TRUE(with_model->next(frame));
    EXPECT_EQ(frame.camera, CameraModel::kinect_v1().scaled_to(512, 424));
    EXPECT_NE(with_model->description().find("camera model given"), std::string::npos) << with_model->description();
  }
}

TEST(OpenNIRoundTrip, DetectorReadsARecordingLikeAnyOtherSource) {
  test::TempDir dir;
  fs::create_directory(dir / "png");
  write_sequence(dir / "png", 3, false);
  ASSERT_EQ(record("--device " + test::quote(device_uri(dir / "png")) + " --frames 3 --out " +
                   test::quote(dir / "take.oni")).exit_code, 0);
  // The noise pattern makes one object wider and taller than any person: keep it (max_object_width 0,
  // max-height 0) so frames have rows.
  const auto r = test::run(test::quote(test::program("rdsf-detect")) + " --source " + test::quote(dir / "take.oni") +
                           " --candidates-only --max_object_width 0 --max-height 0 --out " +
                           test::quote(dir / "out.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The CSV names each frame of the recording: 0, 1, 2.
  std::ifstream csv(dir / "out.csv");
  std::stringstream text;
  text << csv.rdbuf();
  EXPECT_NE(text.str().find("\n2,"), std::string::npos) << text.str().substr(0, 400);
  EXPECT_NE(r.err.find("3 frames"), std::string::npos) << r.err;
}
