#pragma once
// Encoding images as PNG file bytes: the same bytes as cv::imencode(".png", image,
// {IMWRITE_PNG_COMPRESSION, level}) with the system's libpng 1.6 and zlib, in about half the time (the
// sample crops of every miner and labeller are written this way, and their bytes must not change).
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
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf {

struct PngEncodeOptions {
  int zlib_level = 1;       ///< cv::IMWRITE_PNG_COMPRESSION (0 none .. 9 smallest)
  bool direct_path = true;  ///< false: every image goes to cv::imencode (the reference)
};

/// PNG file bytes of `image` (CV_8U or CV_16U, 1, 3 or 4 channels, BGR(A) order), as cv::imencode with
/// {IMWRITE_PNG_COMPRESSION, options.zlib_level} gives them. Throws Error when encoding fails.
std::vector<unsigned char> encode_png(const cv::Mat& image, const PngEncodeOptions& options = {});

}  // namespace rdsf
