#include <gtest/gtest.h>

#include <fstream>

#include <opencv2/imgcodecs.hpp>

#include "rdsf/core/error.hpp"
#include "rdsf/frame/depth_png.hpp"
#include "rdsf/frame/depth_units.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/frame/png_folder_source.hpp"
#include "rdsf/version.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

cv::Mat1w depth_image(std::uint16_t value, cv::Size size = {640, 480}) { return cv::Mat1w(size, value); }

// Expects `body` to throw an Error whose message contains every part.
template <typename F>
void expect_error(F body, const std::vector<std::string>& parts) {
  try {
    body();
    ADD_FAILURE() << "no error thrown";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    for (const std::string& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

/// Reads every frame of `spec`; returns how many.
int drain(const std::string& spec) {
  auto source = open_frame_source(spec);
  DepthFrame frame;
  int frames = 0;
  while (source->next(frame)) ++frames;
  return frames;
}

}  // namespace

TEST(PngFolderSource, ReadsSortedFramesWithMatchingColour) {
  test::TempDir dir;
  cv::imwrite(dir / "b.depth.png", depth_image(2000));
  cv::imwrite(dir / "a.depth.png", depth_image(1000));
  cv::imwrite(dir / "a.rgb.png", cv::Mat3b(480, 640, cv::Vec3b(1, 2, 3)));
  cv::imwrite(dir / "notes.png", cv::Mat1b(4, 4));  // ignored: not NAME.depth.png
  auto source = open_frame_source(dir.path().string());
  EXPECT_EQ(source->frame_count().value(), 2);
  DepthFrame frame;
  ASSERT_TRUE(source->next(frame));
  EXPECT_EQ(frame.name, "a");
  EXPECT_EQ(frame.index, 0);
  EXPECT_EQ(frame.depth_mm(10, 10), 1000);
  ASSERT_TRUE(frame.has_colour());
  EXPECT_EQ(frame.bgr(0, 0), cv::Vec3b(1, 2, 3));
  EXPECT_EQ(frame.camera, CameraModel::kinect_v1());
  ASSERT_TRUE(source->next(frame));
  EXPECT_EQ(frame.name, "b");
  EXPECT_EQ(frame.index, 1);
  EXPECT_EQ(frame.timestamp_us, 33333);
  EXPECT_FALSE(frame.has_colour());
  EXPECT_FALSE(source->next(frame));
}

TEST(PngFolderSource, ListFileAndSingleFile) {
  test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "sub");
  cv::imwrite(dir / "sub/x.depth.png", depth_image(1500, {320, 240}));
  cv::imwrite(dir / "y.depth.png", depth_image(2500, {320, 240}));
  std::ofstream(dir / "list.txt") << "# frames\nsub/x.depth.png\n\n" << (dir / "y.depth.png") << "\n";
  auto source = open_frame_source(dir / "list.txt");
  DepthFrame frame;
  ASSERT_TRUE(source->next(frame));
  EXPECT_EQ(frame.name, "x");
  EXPECT_DOUBLE_EQ(frame.camera.fx_px, 262.5);  // intrinsics follow the image size
  ASSERT_TRUE(source->next(frame));
  EXPECT_EQ(frame.depth_mm(0, 0), 2500);
  EXPECT_FALSE(source->next(frame));

  auto single = open_frame_source(dir / "y.depth.png");
  EXPECT_EQ(single->frame_count().value(), 1);
}

TEST(FrameSourceErrors, MissingPath) {
  expect_error([] { open_frame_source("/no/such/folder"); }, {"/no/such/folder", "no such file"});
}

TEST(FrameSourceErrors, EmptyFolder) {
  test::TempDir dir;
  expect_error([&] { open_frame_source(dir.path().string()); }, {dir.path().string(), "no *.depth.png"});
}

// The names a source gives its frames, known before reading them: a folder's and a list's file stems, in order.
TEST(PngFolderSource, FrameNamesAreTheFileStemsBeforeReading) {
  test::TempDir dir;
  cv::imwrite(dir / "b.depth.png", cv::Mat1w(48, 64, std::uint16_t{1500}));
  cv::imwrite(dir / "a.depth.png", cv::Mat1w(48, 64, std::uint16_t{1500}));
  EXPECT_EQ(open_frame_source(dir.path().string())->frame_names(), (std::vector<std::string>{"a", "b"}));
  std::ofstream(dir / "list.txt") << "b.depth.png\n";
  EXPECT_EQ(open_frame_source(dir / "list.txt")->frame_names(), (std::vector<std::string>{"b"}));
  EXPECT_EQ(index_frame_names(3), (std::vector<std::string>{"0", "1", "2"}));
}

// Another dataset's layout (depth/000001.png, ...): the error says how to read it, and a list file does.
TEST(FrameSourceErrors, FolderOfOtherPngsSaysHowToReadThem) {
  test::TempDir dir;
  cv::imwrite(dir / "000001.png", cv::Mat1w(48, 64, std::uint16_t{1500}));
  cv::imwrite(dir / "000002.png", cv::Mat1w(48, 64, std::uint16_t{1500}));
  expect_error([&] { open_frame_source(dir.path().string()); },
               {dir.path().string(), "no *.depth.png frames (its 2 other PNG files are not taken for depth",
                "ls " + dir.path().string() + "/*.png > frames.txt"});
  std::ofstream(dir / "frames.txt") << "000001.png\n000002.png\n";
  EXPECT_EQ(drain(dir / "frames.txt"), 2);
}

TEST(FrameSourceErrors, EightBitImageAsDepth) {
  test::TempDir dir;
  cv::imwrite(dir / "f.depth.png", cv::Mat1b(480, 640, std::uint8_t{100}));
  expect_error([&] { drain(dir.path().string()); }, {"f.depth.png", "8-bit image given as depth"});
}

TEST(FrameSourceErrors, ColourImageAsDepth) {
  test::TempDir dir;
  cv::imwrite(dir / "f.depth.png", cv::Mat3b(480, 640, cv::Vec3b(1, 2, 3)));
  expect_error([&] { drain(dir.path().string()); }, {"f.depth.png", "3-channel image given as depth"});
}

TEST(FrameSourceErrors, ColourOfAnotherSize) {
  test::TempDir dir;
  cv::imwrite(dir / "f.depth.png", depth_image(1000));
  cv::imwrite(dir / "f.rgb.png", cv::Mat3b(240, 320, cv::Vec3b(1, 2, 3)));
  expect_error([&] { drain(dir.path().string()); }, {"f.rgb.png", "320x240", "640x480"});
}

TEST(FrameSourceErrors, CorruptAndTruncatedPng) {
  test::TempDir dir;
  write_png_atomically(dir / "good.png", depth_image(1234));
  std::ifstream in(dir / "good.png", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string corrupt = bytes;
  corrupt[corrupt.size() / 2] = static_cast<char>(corrupt[corrupt.size() / 2] ^ 0x5a);
  std::ofstream(dir / "corrupt.depth.png", std::ios::binary) << corrupt;
  std::ofstream(dir / "cut.depth.png", std::ios::binary) << bytes.substr(0, bytes.size() - 20);
  std::ofstream(dir / "text.depth.png", std::ios::binary) << "hello, not an image";
  expect_error([&] { read_depth_png(dir / "corrupt.depth.png"); }, {"corrupt.depth.png", "corrupt PNG"});
  expect_error([&] { read_depth_png(dir / "cut.depth.png"); }, {"cut.depth.png", "truncated PNG"});
  expect_error([&] { read_depth_png(dir / "text.depth.png"); }, {"text.depth.png", "not a PNG"});
  EXPECT_EQ(read_depth_png(dir / "good.png")(5, 5), 1234);
}

TEST(FrameSourceErrors, BadListFile) {
  test::TempDir dir;
  std::ofstream(dir / "list.txt") << "a.depth.png\nthis is not a path\n";
  expect_error([&] { open_frame_source(dir / "list.txt"); }, {"list.txt", "line 2", "not a PNG path"});
}

#if RDSF_WITH_OPENNI  // without it: test_package.cpp, WithoutOpenNI
TEST(OpenNISource, NonOpenNIFileIsRefused) {
  test::TempDir dir;
  std::ofstream(dir / "noise.oni", std::ios::binary) << std::string(4096, 'x');
  expect_error([&] { open_frame_source(dir / "noise.oni"); }, {"noise.oni", "not a readable OpenNI recording"});
}

TEST(OpenNISource, TooShortFileIsRefused) {
  test::TempDir dir;
  std::ofstream(dir / "short.oni", std::ios::binary) << "ONI";
  expect_error([&] { open_frame_source(dir / "short.oni"); }, {"short.oni", "not an OpenNI recording"});
}

TEST(OpenNISource, MissingRecording) {
  expect_error([] { open_frame_source("/no/such/take.oni"); }, {"/no/such/take.oni", "no such file"});
}

TEST(OpenNISource, NoDeviceAttached) {
  // CI machines and developer machines have no Kinect: opening the first device must fail cleanly.
  expect_error([] { open_frame_source("openni"); }, {"OpenNI2 device", "no device attached"});
}
#endif

// The median of the nonzero readings, and the note for medians outside a Kinect-class camera's range.
TEST(DepthUnits, MedianOfTheReadingsAndANoteOutsideTheRange) {
  cv::Mat1w depth(4, 4, std::uint16_t{0});
  EXPECT_EQ(median_reading_mm(depth), 0);
  EXPECT_EQ(depth_units_note(depth), "");  // no reading: nothing to say
  depth(0, 0) = 1000;
  depth(0, 1) = 2000;
  depth(0, 2) = 3000;
  EXPECT_EQ(median_reading_mm(depth), 2000);  // the zeros do not count
  EXPECT_EQ(depth_units_note(depth), "");
  depth.setTo(kMaxMedianReadingMm);
  EXPECT_EQ(depth_units_note(depth), "");  // the range's ends are inside
  depth.setTo(kMinMedianReadingMm);
  EXPECT_EQ(depth_units_note(depth), "");
  depth.setTo(kMaxMedianReadingMm + 1);
  EXPECT_NE(depth_units_note(depth).find("median reading is 12001 mm, beyond"), std::string::npos);
  depth.setTo(150);
  EXPECT_NE(depth_units_note(depth).find("median reading is 150 mm, below"), std::string::npos);
  EXPECT_NE(depth_units_note(depth).find("depth_unit_mm: 10 for centimetres"), std::string::npos);
}
