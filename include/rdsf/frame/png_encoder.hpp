#pragma once
// Encoding images as PNG file bytes, two ways (PngEncodeOptions::deflater):
//   - zlib (the default of encode_png): the same bytes as cv::imencode(".png", image,
//     {IMWRITE_PNG_COMPRESSION, level}) with the system's libpng 1.6 and zlib, in about half the time (the
//     sample crops of main at ae93907 and before);
//   - libdeflate: the same filtered rows compressed in one call by libdeflate's zlib compressor (one
//     compressor per thread and level) into one IDAT chunk; other bytes than cv::imencode's, the same pixels
//     when decoded. Sample crops use it (dataset/sample_crop.hpp, kSampleCropPng).
//
// What cv::imencode does with a compression level (OpenCV 4 over libpng 1.6), and the direct path repeats:
//   - chunks: the signature, IHDR (bit depth 8 or 16, colour type grey / RGB / RGBA, deflate, filter 0,
//     no interlace), IDAT chunks of 8192 bytes of the zlib stream (libpng's buffer) and a last shorter one,
//     IEND; each chunk's CRC-32 over its type and data;
//   - rows in PNG order: 16-bit samples big-endian, BGR(A) to RGB(A);
//   - each row filtered by libpng's adaptive choice: of None, Sub, Up, Average and Paeth (PNG specification,
//     section 9; the row above is zeros for the first row), the one whose filtered bytes v have the smallest
//     sum of min(v, 256 - v), the first of them on a tie;
//   - one zlib stream (deflateInit2(level, Z_DEFLATED, 15, 8, Z_DEFAULT_STRATEGY)) fed the filter byte and
//     the filtered bytes row by row, then finished.
// libpng shrinks zlib's window for images whose filtered data is at most 16384 bytes; those images go to
// cv::imencode, as does anything else outside the direct path (other depths or channel counts, levels
// outside 0..9). tests/test_png_encoder.cpp checks the bytes against cv::imencode.
// The libdeflate path: signature, IHDR as above, one IDAT holding libdeflate_zlib_compress(level) of the
// rows filtered as above (any size), IEND; images outside the direct path go to cv::imencode with
// zlib_level. tests/test_png_encoder.cpp checks that cv::imdecode and decode_png give back the pixels.
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf {

enum class PngDeflater {
  zlib,        ///< cv::imencode's bytes
  libdeflate,  ///< libdeflate_zlib_compress at libdeflate_level: faster, other bytes, the same pixels
};

struct PngEncodeOptions {
  int zlib_level = 1;       ///< cv::IMWRITE_PNG_COMPRESSION (0 none .. 9 smallest)
  bool direct_path = true;  ///< false: every image goes to cv::imencode (the reference)
  PngDeflater deflater = PngDeflater::zlib;
  int libdeflate_level = 1;  ///< libdeflate's level (0 none .. 12 smallest), with PngDeflater::libdeflate
};

/// PNG file bytes of `image` (CV_8U or CV_16U, 1, 3 or 4 channels, BGR(A) order): with PngDeflater::zlib as
/// cv::imencode with {IMWRITE_PNG_COMPRESSION, options.zlib_level} gives them; with PngDeflater::libdeflate a
/// PNG of the same pixels. Throws Error when encoding fails or libdeflate_level is outside 0..12.
std::vector<unsigned char> encode_png(const cv::Mat& image, const PngEncodeOptions& options = {});

}  // namespace rdsf
