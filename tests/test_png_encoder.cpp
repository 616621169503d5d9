// The direct PNG encoder (rdsf::encode_png) against cv::imencode with the same compression level: the same
// bytes on random, smooth, constant and real images of every depth and channel count the direct path takes,
// on the sample crops of the miner, and on the sizes that go to cv::imencode (tiny images). The libdeflate
// path (the sample crops' default, kSampleCropPng): on the same images, cv::imdecode and decode_png give back
// exactly the input pixels, from a PNG of one IDAT chunk.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "rdsf/core/error.hpp"
#include "rdsf/dataset/sample_crop.hpp"
#include "rdsf/frame/depth_png.hpp"
#include "rdsf/frame/png_decoder.hpp"
#include "rdsf/frame/png_encoder.hpp"
#include "support/test_support.hpp"

namespace {

std::vector<unsigned char> reference(const cv::Mat& image, int level) {
  std::vector<unsigned char> bytes;
  EXPECT_TRUE(cv::imencode(".png", image, bytes, {cv::IMWRITE_PNG_COMPRESSION, level}));
  return bytes;
}

/// Images of `type` and size: uniform noise, a smooth ramp with a little noise (the filters then differ from
/// row to row), a constant, and sparse values over zeros (a masked depth crop).
std::vector<cv::Mat> images_of(int type, cv::Size size, std::mt19937& random) {
  std::vector<cv::Mat> images;
  const bool wide = CV_MAT_DEPTH(type) == CV_16U;
  const double top = wide ? 65535 : 255;
  cv::Mat noise(size, type);
  cv::randu(noise, 0, top + 1);
  images.push_back(noise);
  cv::Mat ramp(size, CV_MAKETYPE(CV_32F, CV_MAT_CN(type)));
  std::normal_distribution<float> jitter(0, wide ? 3.0f : 1.0f);
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      for (int c = 0; c < ramp.channels(); ++c) {
        ramp.ptr<float>(y)[x * ramp.channels() + c] =
            static_cast<float>((wide ? 2500 + 9 * x + 4 * y : 40 + x + y / 2) + 13 * c) + jitter(random);
      }
    }
  }
  cv::Mat smooth;
  ramp.convertTo(smooth, type);
  images.push_back(smooth);
  images.push_back(cv::Mat(size, type, cv::Scalar::all(wide ? 3000 : 77)));
  cv::Mat sparse = smooth.clone();
  cv::Mat mask(size, CV_8U);
  cv::randu(mask, 0, 4);
  sparse.setTo(cv::Scalar::all(0), mask == 0);
  images.push_back(sparse);
  return images;
}

/// The chunk types of PNG bytes in order ("IHDR IDAT IEND").
std::string chunk_types(const std::vector<unsigned char>& png) {
  std::string types;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::size_t length = (std::size_t{png[at]} << 24) | (std::size_t{png[at + 1]} << 16) |
                               (std::size_t{png[at + 2]} << 8) | png[at + 3];
    if (!types.empty()) types += ' ';
    types.append(reinterpret_cast<const char*>(&png[at + 4]), 4);
    at += length + 12;
  }
  return types;
}

/// Both decoders give back exactly `image` from `png` (a failure message, empty when they do).
std::string decodes_to(const std::vector<unsigned char>& png, const cv::Mat& image) {
  const auto same = [&](const cv::Mat& decoded) {
    return decoded.type() == image.type() && decoded.size() == image.size() &&
           cv::norm(decoded, image, cv::NORM_INF) == 0;
  };
  if (!same(cv::imdecode(png, cv::IMREAD_UNCHANGED))) return "cv::imdecode differs";
  if (!same(rdsf::decode_png("crop.png", png.data(), png.size()))) return "decode_png differs";
  return {};
}

rdsf::PngEncodeOptions libdeflate_at(int level) {
  rdsf::PngEncodeOptions options{1};
  options.deflater = rdsf::PngDeflater::libdeflate;
  options.libdeflate_level = level;
  return options;
}

}  // namespace

TEST(PngEncoder, LibdeflatePathGivesBackThePixelsOfEveryTypeAndSize) {
  std::mt19937 random(29);
  int checked = 0;
  for (int type : {CV_8UC1, CV_8UC3, CV_8UC4, CV_16UC1, CV_16UC3, CV_16UC4}) {
    for (cv::Size size : {cv::Size(64, 128), cv::Size(131, 77), cv::Size(1, 1), cv::Size(64, 64), cv::Size(2, 9000)}) {
      for (const cv::Mat& image : images_of(type, size, random)) {
        const std::vector<int> levels =
            size == cv::Size(64, 128) ? std::vector<int>{rdsf::kSampleCropPng.libdeflate_level, 0, 1, 6, 12}
                                      : std::vector<int>{rdsf::kSampleCropPng.libdeflate_level};
        for (int level : levels) {
          const std::string what = "type " + std::to_string(type) + " " + std::to_string(size.width) + "x" +
                                   std::to_string(size.height) + " level " + std::to_string(level);
          const std::vector<unsigned char> png = rdsf::encode_png(image, libdeflate_at(level));
          ASSERT_EQ(chunk_types(png), "IHDR IDAT IEND") << what;
          ASSERT_EQ(decodes_to(png, image), "") << what;
          ++checked;
        }
      }
    }
  }
  EXPECT_EQ(checked, 6 * 4 * (5 + 4));
  // A region of interest (rows not contiguous), like a crop of a frame.
  cv::Mat3b frame(480, 640);
  cv::randu(frame, 0, 256);
  const cv::Mat3b roi = frame(cv::Rect(301, 117, 64, 128));
  EXPECT_EQ(decodes_to(rdsf::encode_png(roi, rdsf::kSampleCropPng), roi), "");
  EXPECT_THROW(rdsf::encode_png(roi, libdeflate_at(13)), rdsf::Error);
  EXPECT_THROW(rdsf::encode_png(cv::Mat(), rdsf::kSampleCropPng), rdsf::Error);
}

TEST(PngEncoder, SampleCropsAreEncodedByLibdeflate) {
  cv::Mat1w depth(128, 64);
  cv::randu(depth, 0, 9000);
  cv::Mat3b colour(128, 64);
  cv::randu(colour, 0, 256);
  const rdsf::EncodedCrop crop = rdsf::EncodedCrop::encode(depth, colour);
  EXPECT_EQ(crop.depth_png, rdsf::encode_png(depth, rdsf::kSampleCropPng));
  EXPECT_EQ(crop.colour_png, rdsf::encode_png(colour, rdsf::kSampleCropPng));
  EXPECT_NE(crop.depth_png, reference(depth, 1));
  const rdsf::EncodedCrop old = rdsf::EncodedCrop::encode(depth, colour, {1});
  EXPECT_EQ(old.depth_png, reference(depth, 1));
  EXPECT_EQ(old.colour_png, reference(colour, 1));
  EXPECT_EQ(old.hash, crop.hash);  // duplicates hash the pixels
}

TEST(PngEncoder, SameBytesAsImencodeForEveryTypeAndLevel) {
  std::mt19937 random(17);
  int direct = 0;
  for (int type : {CV_8UC1, CV_8UC3, CV_8UC4, CV_16UC1, CV_16UC3, CV_16UC4}) {
    for (cv::Size size : {cv::Size(64, 128), cv::Size(131, 77), cv::Size(640, 48), cv::Size(2, 9000)}) {
      for (const cv::Mat& image : images_of(type, size, random)) {
        const std::vector<int> levels = size == cv::Size(64, 128) ? std::vector<int>{1, 0, 6, 9} : std::vector<int>{1};
        for (int level : levels) {
          const std::string what = "type " + std::to_string(type) + " " + std::to_string(size.width) + "x" +
                                   std::to_string(size.height) + " level " + std::to_string(level);
          ASSERT_EQ(rdsf::encode_png(image, {level}), reference(image, level)) << what;
          ++direct;
        }
      }
    }
  }
  EXPECT_EQ(direct, 6 * 4 * (4 + 3));
}

TEST(PngEncoder, ImagesOfARegionOfInterestAndTinyImagesToo) {
  std::mt19937 random(3);
  cv::Mat3b frame(480, 640);
  cv::randu(frame, 0, 256);
  cv::GaussianBlur(frame, frame, cv::Size(5, 5), 0);
  const cv::Mat3b roi = frame(cv::Rect(301, 117, 64, 128));  // not continuous, like a crop of a frame
  ASSERT_FALSE(roi.isContinuous());
  EXPECT_EQ(rdsf::encode_png(roi), reference(roi, 1));
  // At most 16384 bytes of filtered data: libpng narrows zlib's window; cv::imencode encodes those.
  for (cv::Size size : {cv::Size(1, 1), cv::Size(64, 64), cv::Size(127, 128)}) {
    for (const cv::Mat& image : images_of(CV_8UC1, size, random)) EXPECT_EQ(rdsf::encode_png(image), reference(image, 1));
  }
}

// The zlib path gives the bytes crops had before (cv::imencode's), the default (libdeflate) their pixels.
TEST(PngEncoder, SampleCropsOfRealFramesAreTheBytesTheyWereBeforeOrTheirPixels) {
  RDSF_REQUIRE_REALDATA();
  const std::filesystem::path empty = rdsf::test::realdata_dir() / "empty";
  std::size_t crops = 0;
  for (const auto& entry : std::filesystem::directory_iterator(empty)) {
    const std::string path = entry.path().string();
    if (path.size() < 10 || path.compare(path.size() - 10, 10, ".depth.png") != 0) continue;
    const cv::Mat1w depth = rdsf::read_depth_png(path);
    const std::string colour_path = path.substr(0, path.size() - 10) + ".rgb.png";
    cv::Mat3b colour;
    if (std::filesystem::exists(colour_path)) colour = rdsf::read_colour_png(colour_path, depth.size());
    for (int y = 0; y + 128 <= depth.rows; y += 88) {
      for (int x = 0; x + 64 <= depth.cols; x += 72) {
        const cv::Rect window(x, y, 64, 128);
        const cv::Mat3b colour_crop = colour.empty() ? cv::Mat3b() : colour(window);
        const rdsf::EncodedCrop crop = rdsf::EncodedCrop::encode(depth(window), colour_crop, {1});
        ASSERT_EQ(crop.depth_png, reference(depth(window), 1)) << path << " at " << x << "," << y;
        const rdsf::EncodedCrop fast = rdsf::EncodedCrop::encode(depth(window), colour_crop);
        ASSERT_EQ(decodes_to(fast.depth_png, depth(window)), "") << path << " at " << x << "," << y;
        if (!colour.empty()) {
          ASSERT_EQ(crop.colour_png, reference(colour_crop, 1)) << path << " at " << x << "," << y;
          ASSERT_EQ(decodes_to(fast.colour_png, colour_crop), "") << path << " at " << x << "," << y;
        }
        ++crops;
      }
    }
  }
  EXPECT_GT(crops, 100u);
}

TEST(PngEncoder, TheReferencePathIsImencode) {
  cv::Mat1w image(128, 64);
  cv::randu(image, 0, 9000);
  EXPECT_EQ(rdsf::encode_png(image, {1, /*direct_path=*/false}), reference(image, 1));
  EXPECT_THROW(rdsf::encode_png(cv::Mat()), rdsf::Error);
}
