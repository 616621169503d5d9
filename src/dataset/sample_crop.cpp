#include "rdsf/dataset/sample_crop.hpp"

#include <cstdio>
#include <string_view>

#include "rdsf/core/error.hpp"
#include "rdsf/core/stable_hash.hpp"

namespace rdsf {

std::string depth_crop_hash(const cv::Mat1w& depth_crop_mm) {
  const std::string size = std::to_string(depth_crop_mm.cols) + "x" + std::to_string(depth_crop_mm.rows) + ":";
  std::uint64_t h = fnv1a64(size);
  std::vector<char> bytes(static_cast<std::size_t>(depth_crop_mm.cols) * 2);
  for (int y = 0; y < depth_crop_mm.rows; ++y) {
    const std::uint16_t* row = depth_crop_mm.ptr<std::uint16_t>(y);
    for (int x = 0; x < depth_crop_mm.cols; ++x) {  // little-endian whatever the machine
      bytes[2 * static_cast<std::size_t>(x)] = static_cast<char>(row[x] & 0xff);
      bytes[2 * static_cast<std::size_t>(x) + 1] = static_cast<char>(row[x] >> 8);
    }
    h = fnv1a64(std::string_view(bytes.data(), bytes.size()), h);
  }
  return to_hex16(h);
}

EncodedCrop EncodedCrop::encode(const cv::Mat1w& depth_crop_mm, const cv::Mat3b& colour_crop,
                                const PngEncodeOptions& png) {
  if (depth_crop_mm.empty()) throw Error("sample crop: empty depth crop");
  if (!colour_crop.empty() && colour_crop.size() != depth_crop_mm.size()) {
    throw Error("sample crop: colour crop " + std::to_string(colour_crop.cols) + "x" +
                std::to_string(colour_crop.rows) + " differs in size from the depth crop " +
                std::to_string(depth_crop_mm.cols) + "x" + std::to_string(depth_crop_mm.rows));
  }
  EncodedCrop crop;
  // Fast, still lossless: crops are small and written at mining speed (kSampleCropPng).
  crop.depth_png = encode_png(depth_crop_mm, png);
  if (!colour_crop.empty()) crop.colour_png = encode_png(colour_crop, png);
  crop.hash = depth_crop_hash(depth_crop_mm);
  crop.size = depth_crop_mm.size();
  return crop;
}

std::string crop_stem(std::int64_t id) {
  char text[48];
  std::snprintf(text, sizeof text, "crops/%08lld", static_cast<long long>(id));
  return text;
}

}  // namespace rdsf
