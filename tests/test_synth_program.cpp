// rdsf-synth as a user runs it: the frame-source layout it writes, same seed same bytes, --empty, and
// one-line errors without touching anything for impossible arguments and occupied folders.
#include <gtest/gtest.h>

#include <filesystem>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "rdsf/core/stable_hash.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using rdsf::test::program;
using rdsf::test::quote;
using rdsf::test::run;
using rdsf::test::TempDir;

std::string synth(const std::string& arguments) { return quote(program("rdsf-synth")) + " " + arguments; }

/// Hash of every file of a set except synth.yml (which records the command line), in name order.
std::string hash_set(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().filename() != "synth.yml") names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  std::uint64_t h = 0;
  for (const auto& name : names) h = rdsf::fnv1a64(name + rdsf::test::file_text((dir / name).string()), h);
  return rdsf::to_hex16(h);
}

int count_lines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

TEST(SynthProgram, WritesAFrameSourceWithBoxesAndItsRecipe) {
  TempDir dir("rdsf-synth");
  const std::string out = dir / "set";
  const auto r = run(synth("--out " + quote(out) +
                           " --frames 12 --clip-frames 3 --people 2..3 --seed 4 --size 320x240 --rgb"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out + "/000000.depth.png"));
  EXPECT_TRUE(fs::exists(out + "/000011.rgb.png"));
  const std::string boxes = rdsf::test::file_text(out + "/boxes.csv");
  EXPECT_EQ(boxes.rfind("frame,person,x,y,w,h,visible_fraction,track\n", 0), 0U) << boxes;
  EXPECT_GT(count_lines(boxes), 1);
  // clips.csv: one row per clip of 3 frames, each within the generator's ranges (room_generator.hpp).
  std::istringstream clips(rdsf::test::file_text(out + "/clips.csv"));
  std::string line;
  std::getline(clips, line);
  EXPECT_EQ(line, "clip,first_frame,room,room_width_m,front_wall_m,camera_height_m,pitch_deg,roll_deg,moving,"
                  "noise_factor,eight_bit_step_mm,people,furniture_shapes");
  int rows = 0;
  while (std::getline(clips, line)) {
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
    ASSERT_EQ(f.size(), 13U) << line;
    EXPECT_EQ(std::stoi(f[0]), rows) << line;
    EXPECT_EQ(std::stoi(f[1]), 3 * rows) << line;
    EXPECT_TRUE(f[2] == "room" || f[2] == "corridor" || f[2] == "open-plan") << line;
    EXPECT_GE(std::stod(f[5]), 0.5) << line;
    EXPECT_LE(std::stod(f[5]), 1.6) << line;
    EXPECT_LE(std::abs(std::stod(f[7])), 3.0) << line;
    EXPECT_TRUE(f[8] == "0" || f[8] == "1") << line;
    EXPECT_GE(std::stod(f[9]), 1.0) << line;
    EXPECT_GE(std::stoi(f[11]), 2) << line;
    EXPECT_LE(std::stoi(f[11]), 3) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 4);
  const std::string info = rdsf::test::file_text(out + "/synth.yml");
  EXPECT_NE(info.find("seed: 4"), std::string::npos) << info;
  EXPECT_NE(info.find("fx="), std::string::npos) << info;
  auto source = rdsf::open_frame_source(out);
  ASSERT_EQ(source->frame_count().value_or(0), 12);
  rdsf::DepthFrame frame;
  ASSERT_TRUE(source->next(frame));
  EXPECT_EQ(frame.name, "000000");
  EXPECT_EQ(frame.depth_mm.cols, 320);
  EXPECT_TRUE(frame.has_colour());
  EXPECT_DOUBLE_EQ(frame.camera.fx_px, 262.5);
}

TEST(SynthProgram, FieldOfViewGivesACentredPinholeInCameraYmlAndTheSameScenes) {
  TempDir dir("rdsf-synth");
  const std::string common = " --frames 4 --clip-frames 2 --people 2..3 --seed 5";
  ASSERT_EQ(run(synth("--out " + quote(dir / "k") + common + " --size 320x240")).exit_code, 0);
  const auto r = run(synth("--out " + quote(dir / "d") + common + " --size 424x240 --fov 87x58"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir / "k/camera.yml")) << "the Kinect v1's model needs no camera.yml";
  ASSERT_TRUE(fs::exists(dir / "d/camera.yml"));
  auto source = rdsf::open_frame_source(dir / "d");
  rdsf::DepthFrame frame;
  ASSERT_TRUE(source->next(frame));
  EXPECT_EQ(frame.depth_mm.cols, 424);
  const double pi = 3.14159265358979323846;
  EXPECT_NEAR(frame.camera.fx_px, 212.0 / std::tan(43.5 * pi / 180.0), 1e-9);  // 223.40 px
  EXPECT_NEAR(frame.camera.fy_px, 120.0 / std::tan(29.0 * pi / 180.0), 1e-9);  // 216.49 px
  EXPECT_DOUBLE_EQ(frame.camera.cx_px, 211.5);
  EXPECT_DOUBLE_EQ(frame.camera.cy_px, 119.5);
  // the same rooms and people, seen wider: every track of the Kinect v1's view is in the wider one
  const auto tracks = [&](const std::string& set) {
    std::set<std::string> ids;
    std::istringstream rows(rdsf::test::file_text(dir / (set + "/boxes.csv")));
    std::string row;
    std::getline(rows, row);
    while (std::getline(rows, row)) ids.insert(row.substr(row.rfind(',') + 1));
    return ids;
  };
  const std::set<std::string> kinect = tracks("k"), wide = tracks("d");
  EXPECT_FALSE(kinect.empty());
  for (const std::string& id : kinect) EXPECT_EQ(wide.count(id), 1U) << "track " << id;
  // a re-render with --force and without --fov takes the old camera.yml away
  ASSERT_EQ(run(synth("--out " + quote(dir / "d") + common + " --size 424x240 --force")).exit_code, 0);
  EXPECT_FALSE(fs::exists(dir / "d/camera.yml"));
}

TEST(SynthProgram, SameSeedSameBytesOtherSeedOtherBytes) {
  TempDir dir("rdsf-synth");
  const std::string args = " --frames 4 --people 1..2 --size 320x240 --rgb --seed ";
  ASSERT_EQ(run(synth("--out " + quote(dir / "a") + args + "9")).exit_code, 0);
  ASSERT_EQ(run(synth("--out " + quote(dir / "b") + args + "9")).exit_code, 0);
  ASSERT_EQ(run(synth("--out " + quote(dir / "c") + args + "10")).exit_code, 0);
  EXPECT_EQ(hash_set(dir.path() / "a"), hash_set(dir.path() / "b"));
  EXPECT_NE(hash_set(dir.path() / "a"), hash_set(dir.path() / "c"));
}

TEST(SynthProgram, EmptyWritesNoBoxes) {
  TempDir dir("rdsf-synth");
  const auto r = run(synth("--out " + quote(dir / "e") + " --frames 3 --people 2..3 --empty --size 160x120"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(rdsf::test::file_text(dir / "e/boxes.csv"), "frame,person,x,y,w,h,visible_fraction,track\n");
  EXPECT_TRUE(fs::exists(dir / "e/000002.depth.png"));
}

TEST(SynthProgram, ImpossibleArgumentsGiveOneLineAndTouchNothing) {
  TempDir dir("rdsf-synth");
  for (const std::string bad :
       {"--people 5..2", "--people two", "--size 100x75", "--size 640", "--frames 0", "--camera-height 0.1..1",
        "--camera-pitch 6..-3", "--camera-roll 45", "--camera-yaw -5", "--moving-camera 1.5", "--camera-speed 3",
        "--clutter 50", "--clutter 2.5", "--corridors 0.7 --open-plan 0.7", "--eight-bit -0.1",
        "--eight-bit-step 0..10", "--xtion 2", "--children 1.1", "--sitting -1", "--groups 1.2", "--outfits yes",
        "--poses 0", "--bodies x", "--room-kinds none", "--coherent-holes 9", "--coherent-holes -1",
        "--fov 87", "--fov 10x58", "--fov 87x160", "--fov wide", "--camera-offset 1"}) {
    const auto r = run(synth("--out " + quote(dir / "x") + " " + bad));
    EXPECT_NE(r.exit_code, 0) << bad;
    EXPECT_EQ(count_lines(r.err), 1) << bad << ": " << r.err;
    EXPECT_NE(r.err.find(bad.substr(0, bad.find(' '))), std::string::npos) << bad << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir / "x")) << bad << " created the output folder";
  }
}

TEST(SynthProgram, AnOccupiedFolderIsReplacedOnlyWithForce) {
  TempDir dir("rdsf-synth");
  const std::string out = dir / "set";
  ASSERT_EQ(run(synth("--out " + quote(out) + " --frames 3 --people 1..1 --size 160x120 --seed 1")).exit_code,
            0);
  const std::string before = rdsf::test::file_text(out + "/000000.depth.png");
  const std::string boxes_before = rdsf::test::file_text(out + "/boxes.csv");
  const auto refused =
      run(synth("--out " + quote(out) + " --frames 2 --people 1..1 --size 160x120 --seed 2"));
  EXPECT_NE(refused.exit_code, 0);
  EXPECT_EQ(count_lines(refused.err), 1) << refused.err;
  EXPECT_NE(refused.err.find("--force"), std::string::npos) << refused.err;
  EXPECT_EQ(rdsf::test::file_text(out + "/000000.depth.png"), before);
  EXPECT_EQ(rdsf::test::file_text(out + "/boxes.csv"), boxes_before);
  EXPECT_TRUE(fs::exists(out + "/000002.depth.png"));

  // a folder of other frames is refused too
  fs::create_directories(dir / "other");
  std::ofstream(dir / "other/kitchen.depth.png") << "x";
  EXPECT_NE(run(synth("--out " + quote(dir / "other") + " --frames 1 --size 160x120")).exit_code, 0);
  EXPECT_EQ(rdsf::test::file_text(dir / "other/kitchen.depth.png"), "x");

  const auto forced =
      run(synth("--out " + quote(out) + " --frames 2 --people 1..1 --size 160x120 --seed 2 --force"));
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_NE(rdsf::test::file_text(out + "/000000.depth.png"), before);
  EXPECT_FALSE(fs::exists(out + "/000002.depth.png")) << "a frame of the replaced set was left behind";
}

}  // namespace
