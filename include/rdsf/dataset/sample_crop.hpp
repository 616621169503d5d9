#pragma once
// The crops of a sample in a sample set: crops/NNNNNNNN.depth.png (16-bit depth in millimetres, window
// sized, 64x128 by default) and crops/NNNNNNNN.rgb.png (8-bit colour) when the frame had colour; NNNNNNNN
// is the sample id, zero-padded to 8 digits. Encoding is split from writing so that it can run in parallel.
// Crops are lossless PNGs; their bytes depend on the encoder (kSampleCropPng), their pixels do not, and
// duplicates are found by depth_crop_hash of the pixels, so sets written with other crop bytes (main at
// ae93907 and before: cv::imencode's) read and deduplicate the same.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/frame/png_encoder.hpp"

namespace rdsf {

/// How every sample crop is encoded (the writer, the miner, the labeller; the one place that decides):
/// libdeflate's compressor at level 1 on the direct encoder's filtered rows (issue 17: chosen by measurement,
/// docs/performance.md). {1} gives the bytes of cv::imencode with compression 1, as sets held before.
inline constexpr PngEncodeOptions kSampleCropPng{1, true, PngDeflater::libdeflate, 1};

/// Stable hash (16 hex digits) of a depth crop's size and values; equal crops give equal hashes on every
/// machine.
std::string depth_crop_hash(const cv::Mat1w& depth_crop_mm);

struct EncodedCrop {
  std::vector<unsigned char> depth_png;   ///< the depth crop as PNG bytes
  std::vector<unsigned char> colour_png;  ///< the colour crop as PNG bytes, empty without colour
  std::string hash;                       ///< depth_crop_hash() of the depth crop
  cv::Size size;                          ///< size of the crops

  /// Encodes a depth crop (CV_16UC1) and an optional colour crop (CV_8UC3, same size) with `png`; throws
  /// Error when the crop is empty or the sizes differ.
  static EncodedCrop encode(const cv::Mat1w& depth_crop_mm, const cv::Mat3b& colour_crop = {},
                            const PngEncodeOptions& png = kSampleCropPng);
};

/// "crops/00000042" relative to the set: add ".depth.png" or ".rgb.png".
std::string crop_stem(std::int64_t id);


}  // namespace rdsf
