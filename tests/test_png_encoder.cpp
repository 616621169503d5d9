// The direct PNG encoder (rdsf::encode_png) against cv::imencode with the same compression level: the same
// bytes on random, smooth, constant and real images of every depth and channel count the direct path takes,
// on the sample crops of the miner, and on the sizes that go to cv::imencode (tiny images).
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

}  // namespace

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

TEST(PngEncoder, SampleCropsOfRealFramesAreTheBytesTheyWereBefore) {
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
        const rdsf::EncodedCrop crop =
            rdsf::EncodedCrop::encode(depth(window), colour.empty() ? cv::Mat3b() : colour(window));
        ASSERT_EQ(crop.depth_png, reference(depth(window), 1)) << path << " at " << x << "," << y;
        if (!colour.empty()) {
          ASSERT_EQ(crop.colour_png, reference(colour(window), 1)) << path << " at " << x << "," << y;
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
