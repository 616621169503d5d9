// OpenCV's image codecs opened at their first use (rdsf/frame/image_codecs.hpp): a program that reads plain
// PNGs never loads libopencv_imgcodecs (nor the ~130 libraries behind it); one that meets a PNG outside the
// direct path opens the module beside librdsf and gives what it gave before; the calls are OpenCV's.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <libdeflate.h>
#include <opencv2/imgcodecs.hpp>

#include "rdsf/core/durable_io.hpp"
#include "rdsf/frame/image_codecs.hpp"
#include "rdsf/frame/png_encoder.hpp"
#include "support/depth_scenes.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

using Bytes = std::vector<unsigned char>;

/// `png` with a private ancillary chunk "rdSf" after IHDR: a valid PNG that libpng decodes to the same
/// pixels but the direct path leaves to OpenCV (png_decoder.hpp).
Bytes with_private_chunk(const Bytes& png) {
  const std::size_t after_ihdr = 8 + 4 + 4 + 13 + 4;
  Bytes out(png.begin(), png.begin() + static_cast<std::ptrdiff_t>(after_ihdr));
  const Bytes chunk = {0, 0, 0, 2, 'r', 'd', 'S', 'f', 'h', 'i'};
  out.insert(out.end(), chunk.begin(), chunk.end());
  const std::uint32_t crc = libdeflate_crc32(0, &chunk[4], 6);
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<unsigned char>(crc >> s));
  out.insert(out.end(), png.begin() + static_cast<std::ptrdiff_t>(after_ihdr), png.end());
  return out;
}

/// rdsf-detect on `folder` with the loader's trace (glibc's LD_DEBUG=files) on standard error.
test::RunResult detect_traced(const std::string& folder, const std::string& csv) {
  return test::run("LD_DEBUG=files " + test::quote(test::program("rdsf-detect")) + " --source " +
                   test::quote(folder) + " --out " + test::quote(csv));
}

}  // namespace

TEST(ImageCodecs, ProgramsOpenOpenCvsCodecsOnlyForAFileOutsideTheDirectPath) {
  if (image_codecs_module_path().empty()) GTEST_SKIP() << "a static librdsf links OpenCV's codecs";
  test::TempDir dir;
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {300, 100, 40, 360}, 2000);
  const Bytes plain = encode_png(frame.depth_mm);
  std::filesystem::create_directories(dir / "plain");
  std::filesystem::create_directories(dir / "other");
  write_file_durably(dir / "plain/scene.depth.png", plain);
  write_file_durably(dir / "other/scene.depth.png", with_private_chunk(plain));

  const test::RunResult direct = detect_traced(dir / "plain", dir / "plain.csv");
  ASSERT_EQ(direct.exit_code, 0) << direct.err.substr(direct.err.size() > 2000 ? direct.err.size() - 2000 : 0);
  ASSERT_NE(direct.err.find("librdsf"), std::string::npos) << "no loader trace: LD_DEBUG ignored?";
  EXPECT_EQ(direct.err.find("imgcodecs"), std::string::npos) << "libopencv_imgcodecs loaded for plain PNGs";
  EXPECT_EQ(direct.err.find("rdsf_image_codecs"), std::string::npos);

  const test::RunResult opened = detect_traced(dir / "other", dir / "other.csv");
  ASSERT_EQ(opened.exit_code, 0) << opened.err.substr(opened.err.size() > 2000 ? opened.err.size() - 2000 : 0);
  EXPECT_NE(opened.err.find(image_codecs_module_path()), std::string::npos) << "the module was not opened";
  EXPECT_NE(opened.err.find("libopencv_imgcodecs"), std::string::npos);
  // The same frame, the same rows (candidates, boxes, scores).
  const std::string rows = test::file_text(dir / "plain.csv");
  EXPECT_GT(std::count(rows.begin(), rows.end(), '\n'), 1) << rows;
  EXPECT_EQ(test::file_text(dir / "other.csv"), rows);
}

// A librdsf without its module beside it (a copy moved alone): the first PNG OpenCV must write is a one-line
// error naming the module's path, and the program exits 1; plain PNGs are still read without it.
TEST(ImageCodecs, AMissingModuleIsAOneLineErrorNamingIt) {
  const std::string module = image_codecs_module_path();
  if (module.empty()) GTEST_SKIP() << "a static librdsf links OpenCV's codecs";
  test::TempDir dir;
  const std::filesystem::path library_dir = std::filesystem::path(module).parent_path();
  const std::filesystem::path lib = dir.path() / "lib";
  std::filesystem::create_directories(lib);
  for (const auto& entry : std::filesystem::directory_iterator(library_dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("librdsf.so.", 0) == 0 && !entry.is_symlink()) {
      std::filesystem::copy_file(entry.path(), lib / name);
      std::filesystem::create_symlink(name, lib / name.substr(0, name.rfind('.')));
    }
  }
  // LD_LIBRARY_PATH comes before the programs' RUNPATH: the copy is the librdsf they load.
  const std::string run_alone = "LD_LIBRARY_PATH=" + test::quote(lib.string()) + " ";
  const test::RunResult synth = test::run(run_alone + test::quote(test::program("rdsf-synth")) + " --out " +
                                          test::quote(dir / "synth") + " --frames 1 --seed 1");
  EXPECT_EQ(synth.exit_code, 1) << synth.err;
  const std::string missing = (lib / "librdsf_image_codecs.so").string();
  EXPECT_NE(synth.err.find("rdsf-synth: error: " + missing + ": cannot load OpenCV's image codecs ("),
            std::string::npos) << synth.err;
  EXPECT_EQ(synth.err.find(missing, synth.err.find(missing) + 1), std::string::npos) << "named twice: " << synth.err;
  EXPECT_EQ(std::count(synth.err.begin(), synth.err.end(), '\n'), 2) << synth.err;  // its start line and the error

  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {300, 100, 40, 360}, 2000);
  std::filesystem::create_directories(dir / "plain");
  write_file_durably(dir / "plain/scene.depth.png", encode_png(frame.depth_mm));
  const test::RunResult detect =
      test::run(run_alone + test::quote(test::program("rdsf-detect")) + " --source " + test::quote(dir / "plain") +
                " --candidates-only --out " + test::quote(dir / "p.csv"));
  EXPECT_EQ(detect.exit_code, 0) << detect.err;  // (the copy finds no shipped model: candidates only)
  EXPECT_NE(test::file_text(dir / "p.csv").find("scene,0,"), std::string::npos);
}

TEST(ImageCodecs, CallsGiveWhatOpenCvGives) {
  DepthFrame frame = test::wall_frame(3000);
  test::paint(frame, {100, 50, 80, 300}, 1500);
  // Encoding: OpenCV's default parameters and a given level, byte for byte.
  std::vector<unsigned char> ours, theirs;
  ASSERT_TRUE(opencv_encode_png(frame.depth_mm, ours, kOpenCvDefaultPngParams));
  ASSERT_TRUE(cv::imencode(".png", frame.depth_mm, theirs));
  EXPECT_EQ(ours, theirs);
  ASSERT_TRUE(opencv_encode_png(frame.depth_mm, ours, 6));
  ASSERT_TRUE(cv::imencode(".png", frame.depth_mm, theirs, {cv::IMWRITE_PNG_COMPRESSION, 6}));
  EXPECT_EQ(ours, theirs);
  // Decoding: unchanged (16-bit stays 16-bit) and as colour; a file OpenCV cannot read is an empty image.
  const cv::Mat depth = opencv_decode_image(ours.data(), ours.size(), DecodedAs::unchanged);
  ASSERT_EQ(depth.type(), CV_16UC1);
  EXPECT_EQ(cv::countNonZero(depth != frame.depth_mm), 0);
  const cv::Mat colour = opencv_decode_image(ours.data(), ours.size(), DecodedAs::colour);
  EXPECT_EQ(colour.type(), CV_8UC3);
  const unsigned char junk[] = {'n', 'o', 't', ' ', 'a', 'n', ' ', 'i', 'm', 'a', 'g', 'e'};
  EXPECT_TRUE(opencv_decode_image(junk, sizeof junk, DecodedAs::unchanged).empty());
  EXPECT_NO_THROW(open_image_codecs());  // open (or linked) already: nothing more
  // The module sits beside the shared library that opens it.
  const std::string module = image_codecs_module_path();
  if (!module.empty()) {
    EXPECT_TRUE(std::filesystem::is_regular_file(module)) << module;
  }
}
