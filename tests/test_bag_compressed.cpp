// Bags whose images are sensor_msgs/CompressedImage, as robots record image_transport's compressed topics
// (`rosbag record /camera/depth/image_raw/compressedDepth /camera/rgb/image_raw/compressed`): written by
// scripts/frames-to-bag.py --compressed-depth / --compressed-colour from ../shared/realdata/people, read by the
// bag source (rdsf/frame/bag_source.hpp, frame/compressed_image.hpp). Skips like test_bag_source.cpp.
#include <gtest/gtest.h>

#include <fstream>

#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/pipeline/parallel_pipeline.hpp"
#include "rdsf/pipeline/people_detector.hpp"
#include "support/bag_writer.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

using test::all_frames;
using test::same_pixels;
std::string people_dir() { return test::people_frames_dir(); }

}  // namespace

// Lossless compression (compressedDepth png, colour png) reads back the PNG folder's depth and colour frame for
// frame, with the camera model of the image topic's camera_info; RVL too (six frames: the script's RVL writer
// is slow Python).
TEST(BagCompressed, LosslessCompressedTopicsReadAsThePngFolder) {
  RDSF_REQUIRE_BAG_WRITER();
  test::TempDir dir("rdsf-bag-compressed");
  const std::vector<DepthFrame> png_frames = all_frames(*open_frame_source(people_dir()));
  const std::string bag =
      test::write_bag(people_dir(), dir / "png.bag", "--compressed-depth png --compressed-colour png");
  auto source = open_frame_source(bag);
  EXPECT_NE(source->description().find("depth /camera/depth/image_raw/compressedDepth (16UC1; compressedDepth png, "
                                       "46 frames), colour /camera/rgb/image_raw/compressed, camera model from "
                                       "/camera/depth/camera_info"),
            std::string::npos)
      << source->description();
  const std::vector<DepthFrame> frames = all_frames(*source);
  ASSERT_EQ(frames.size(), png_frames.size());
  int with_colour = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    ASSERT_TRUE(same_pixels(frames[i].depth_mm, png_frames[i].depth_mm)) << png_frames[i].name;
    ASSERT_TRUE(same_pixels(frames[i].bgr, png_frames[i].bgr)) << png_frames[i].name;
    EXPECT_EQ(frames[i].camera, png_frames[i].camera);
    with_colour += frames[i].has_colour() ? 1 : 0;
  }
  EXPECT_EQ(with_colour, 14);

  const std::string rvl = test::write_bag(people_dir(), dir / "rvl.bag", "--compressed-depth rvl --count 6");
  const std::vector<DepthFrame> rvl_frames = all_frames(*open_frame_source(rvl));
  ASSERT_EQ(rvl_frames.size(), 6u);
  for (std::size_t i = 0; i < rvl_frames.size(); ++i) {
    EXPECT_TRUE(same_pixels(rvl_frames[i].depth_mm, png_frames[i].depth_mm)) << png_frames[i].name;
    EXPECT_TRUE(same_pixels(rvl_frames[i].bgr, png_frames[i].bgr)) << png_frames[i].name;  // raw rgb8
  }
}

// 32FC1 compressedDepth is the transport's inverse-depth quantisation: each reading back within its step
// d^2 / A (A = 100 x 101) and a millimetre, readings beyond its 10 m maximum dropped, no reading added; and a
// depth image registered to colour whose only camera_info is the colour camera's (layout registered).
TEST(BagCompressed, FloatCompressedDepthIsWithinTheQuantisationStep) {
  RDSF_REQUIRE_BAG_WRITER();
  test::TempDir dir("rdsf-bag-compressed");
  const std::vector<DepthFrame> png_frames = all_frames(*open_frame_source(people_dir()));
  const std::string bag = test::write_bag(people_dir(), dir / "f32.bag",
                                          "--compressed-depth png --depth-encoding 32FC1 --layout registered --count 12");
  auto source = open_frame_source(bag);
  EXPECT_NE(source->description().find("camera model from /camera/rgb/camera_info"), std::string::npos)
      << source->description();
  const std::vector<DepthFrame> frames = all_frames(*source);
  ASSERT_EQ(frames.size(), 12u);
  std::int64_t readings = 0, off_by_more_than_1mm = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const cv::Mat1w& got = frames[i].depth_mm;
    const cv::Mat1w& want = png_frames[i].depth_mm;
    ASSERT_EQ(got.size(), want.size());
    EXPECT_EQ(frames[i].camera, png_frames[i].camera);
    for (int y = 0; y < want.rows; ++y) {
      for (int x = 0; x < want.cols; ++x) {
        const int d = want(y, x);
        if (d == 0 || d >= 10000) {
          ASSERT_EQ(got(y, x), 0) << png_frames[i].name << " (" << x << ", " << y << ")";
          continue;
        }
        ++readings;
        const double step_mm = 1e-3 * d * d / (100.0 * 101.0);
        ASSERT_LE(std::abs(got(y, x) - d), step_mm + 1.0) << png_frames[i].name << " (" << x << ", " << y << ")";
        off_by_more_than_1mm += std::abs(got(y, x) - d) > 1 ? 1 : 0;
      }
    }
  }
  EXPECT_GT(readings, 1000000);
  EXPECT_GT(off_by_more_than_1mm, 0);  // the quantisation is lossy: the comparison above compared it
}

// A damaged compressedDepth message: the first refused when the topic is chosen, a later one when it is read;
// one line naming the bag, the topic, the image and the problem.
TEST(BagCompressed, DamagedCompressedImagesAreOneLineErrors) {
  RDSF_REQUIRE_BAG_WRITER();
  test::TempDir dir("rdsf-bag-compressed");
  const std::string bag = test::write_bag(people_dir(), dir / "good.bag", "--compressed-depth png --count 4");
  const auto damage = [&](const std::string& out, int image, const std::string& topic_end = "compressedDepth",
                          const std::string& from = "") {
    const test::RunResult r = test::run(
        "/usr/bin/python3 -c \"import rosbag; i=rosbag.Bag('" + (from.empty() ? bag : from) + "'); o=rosbag.Bag('" +
        out + "','w'); n=0\n"
        "for t,m,s in i.read_messages():\n"
        "    if t.endswith('" + topic_end + "'):\n"
        "        if n == " + std::to_string(image) + ": m.data = m.data[:12] + m.data[12:40]\n"
        "        n += 1\n"
        "    o.write(t, m, s)\n"
        "o.close()\"");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return out;
  };
  const std::string first = damage(dir / "first.bag", 0);
  std::string e = test::error_message([&] { open_frame_source(first); });
  EXPECT_EQ(e.rfind(first + ": topic /camera/depth/image_raw/compressedDepth: image 0: truncated PNG", 0), 0u) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;

  const std::string third = damage(dir / "third.bag", 2);
  auto source = open_frame_source(third);
  DepthFrame frame;
  EXPECT_TRUE(source->next(frame));
  EXPECT_TRUE(source->next(frame));
  e = test::error_message([&] { source->next(frame); });
  EXPECT_EQ(e.rfind(third + ": topic /camera/depth/image_raw/compressedDepth: image 2: truncated PNG", 0), 0u) << e;

  // A compressed colour topic whose first image cannot be decoded is not used, and said so; depth goes on.
  const std::string colour = test::write_bag(people_dir(), dir / "colour.bag", "--compressed-colour png --count 2");
  const std::string bad_colour = damage(dir / "bad-colour.bag", 0, "compressed", colour);
  auto without_colour = open_frame_source(bad_colour);
  EXPECT_NE(without_colour->description().find("no colour (/camera/rgb/image_raw/compressed cannot be decoded: not used)"),
            std::string::npos)
      << without_colour->description();
  EXPECT_EQ(all_frames(*without_colour).size(), 2u);
}

// A recorder that kept both a camera's raw topics and their compressed twins: the raw ones are read (the same
// images, lossless); --depth-topic still chooses the compressed one.
TEST(BagCompressed, RawTopicsAreChosenOverTheirCompressedTwins) {
  RDSF_REQUIRE_BAG_WRITER();
  test::TempDir dir("rdsf-bag-compressed");
  const std::string raw = test::write_bag(people_dir(), dir / "raw.bag", "--count 3");
  const std::string compressed =
      test::write_bag(people_dir(), dir / "compressed.bag", "--count 3 --compressed-depth png --compressed-colour png");
  const std::string both = dir / "both.bag";
  const test::RunResult r = test::run(
      "/usr/bin/python3 -c \"import rosbag; o=rosbag.Bag('" + both + "','w')\n"
      "for f in ['" + raw + "', '" + compressed + "']:\n"
      "    for t,m,s in rosbag.Bag(f).read_messages():\n"
      "        if f.endswith('raw.bag') or 'compressed' in t: o.write(t, m, s)\n"
      "o.close()\"");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto source = open_frame_source(both);
  EXPECT_NE(source->description().find("depth /camera/depth/image_raw (16UC1, 3 frames), colour /camera/rgb/image_raw,"),
            std::string::npos)
      << source->description();
  FrameSourceOptions options;
  options.depth_topic = "/camera/depth/image_raw/compressedDepth";
  options.colour_topic = "/camera/rgb/image_raw/compressed";
  auto chosen = open_frame_source(both, options);
  EXPECT_NE(chosen->description().find("depth /camera/depth/image_raw/compressedDepth"), std::string::npos)
      << chosen->description();
  const std::vector<DepthFrame> a = all_frames(*source), b = all_frames(*chosen);
  ASSERT_EQ(a.size(), 3u);
  ASSERT_EQ(b.size(), 3u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(same_pixels(a[i].depth_mm, b[i].depth_mm)) << i;
    EXPECT_TRUE(same_pixels(a[i].bgr, b[i].bgr)) << i;
  }
}

// JPEG colour (the usual `.../image_raw/compressed`): read close to the PNG folder's colour, the depth exact.
// The script needs python3-opencv for JPEG (scripts/setup.sh installs it; skipped without it). The JPEG is
// decoded by OpenCV's codecs, which the library opens at their first use (frame/image_codecs.hpp).
TEST(BagCompressed, JpegColourReadsCloseToTheFolders) {
  RDSF_REQUIRE_BAG_WRITER();
  if (test::run("/usr/bin/python3 -c 'import cv2'").exit_code != 0) {
    GTEST_SKIP() << "python3-opencv missing: the script cannot write JPEG colour";
  }
  test::TempDir dir("rdsf-bag-compressed");
  const std::vector<DepthFrame> png_frames = all_frames(*open_frame_source(people_dir()));
  const std::string bag = test::write_bag(people_dir(), dir / "jpeg.bag", "--compressed-colour jpeg");
  const std::vector<DepthFrame> frames = all_frames(*open_frame_source(bag));
  ASSERT_EQ(frames.size(), png_frames.size());
  int with_colour = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_TRUE(same_pixels(frames[i].depth_mm, png_frames[i].depth_mm)) << png_frames[i].name;
    ASSERT_EQ(frames[i].has_colour(), png_frames[i].has_colour()) << png_frames[i].name;
    if (!frames[i].has_colour()) continue;
    ++with_colour;
    const double mean_difference = cv::norm(frames[i].bgr, png_frames[i].bgr, cv::NORM_L1) /
                                   static_cast<double>(frames[i].bgr.total() * 3);
    EXPECT_LT(mean_difference, 4.0) << png_frames[i].name;  // JPEG's loss, channels in the right order
    EXPECT_GT(mean_difference, 0.0) << png_frames[i].name;  // it is the JPEG that was read
  }
  EXPECT_EQ(with_colour, 14);
}

// run_in_frame_order decodes a bag's frames on its workers (BagSource::next_deferred: messages read and paired
// in order, images decoded apart): on 2 threads the same scores and people, frame for frame, as the frames
// read one by one with next(); a damaged message stops the run with its one-line error from the worker.
TEST(BagCompressed, FramesDecodedOnTheWorkersAreTheFramesReadInOrder) {
  RDSF_REQUIRE_BAG_WRITER();
  test::TempDir dir("rdsf-bag-compressed");
  const std::string bag = test::write_bag(people_dir(), dir / "png.bag", "--compressed-depth png --compressed-colour png");
  const std::string model = resolve_model("people", (test::realdata_dir() / "no-models-here").string());
  PeopleDetector in_order(model), on_workers(model);
  std::vector<PipelineFrame> expected;
  for (const DepthFrame& f : all_frames(*open_frame_source(bag))) expected.push_back(in_order.pipeline().process(f));
  ASSERT_EQ(expected.size(), 46u);
  auto source = open_frame_source(bag);
  std::size_t i = 0;
  int people = 0;
  const std::int64_t handed = run_in_frame_order(
      on_workers.pipeline(), *source, CameraModel{}, {2, 0}, [&](const DepthFrame& f, PipelineFrame& r) {
        EXPECT_EQ(f.name, std::to_string(i));
        EXPECT_EQ(r.scores, expected[i].scores) << i;
        EXPECT_EQ(r.person, expected[i].person) << i;
        for (int p : r.person) people += p != 0 ? 1 : 0;
        ++i;
        return true;
      });
  EXPECT_EQ(handed, 46);
  EXPECT_GT(people, 30);  // the comparison compared people
  EXPECT_NE(source->summary().find("paired with 14 of 46 depth frames"), std::string::npos) << source->summary();

  const std::string damaged = dir / "damaged.bag";
  const test::RunResult r = test::run(
      "/usr/bin/python3 -c \"import rosbag; o=rosbag.Bag('" + damaged + "','w'); n=0\n"
      "for t,m,s in rosbag.Bag('" + bag + "').read_messages():\n"
      "    if t.endswith('compressedDepth'):\n"
      "        if n == 30: m.data = m.data[:40]\n"
      "        n += 1\n"
      "    o.write(t, m, s)\n"
      "o.close()\"");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  PeopleDetector again(model);
  auto broken = open_frame_source(damaged);
  const std::string e = test::error_message(
      [&] { run_in_frame_order(again.pipeline(), *broken, CameraModel{}, {2, 0}, {}); });
  EXPECT_EQ(e.rfind(damaged + ": topic /camera/depth/image_raw/compressedDepth: image 30: truncated PNG", 0), 0u) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}
