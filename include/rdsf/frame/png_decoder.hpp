#pragma once
// Decoding PNG file bytes in memory, with the checks that turn bad files into one-line errors.
//
// Every chunk's CRC is checked first (libdeflate's crc32), so a truncated or damaged file is reported as
// "truncated PNG (...)" or "corrupt PNG (CRC error in ...)". Then the common, plain PNGs are decoded by a
// direct path: one zlib inflate of the concatenated IDAT data into the exact size the header implies
// (libdeflate; the Adler-32 of the stream is checked), the five PNG row filters undone in place, and the
// samples converted to what cv::imdecode(IMREAD_UNCHANGED) returns (16-bit samples byte-swapped to host
// order, RGB to BGR, RGBA to BGRA). The direct path takes only files it decodes exactly as libpng would:
// bit depth 8 or 16; colour type grey, RGB or RGBA; not interlaced; no chunks other than IHDR, IDAT, IEND
// and those libpng reads without changing the pixels cv::imdecode gets (tEXt, zTXt, iTXt, tIME, pHYs,
// gAMA, cHRM, sRGB, bKGD, sBIT: no transform is asked for); IDAT chunks consecutive; the
// zlib stream ending exactly at the end of the IDAT data and giving exactly rows x (1 + row bytes) bytes;
// every row's filter type 0..4. Any other file (palette, low bit depth, interlace, gamma or colour-profile
// chunks, or any fault the direct path meets) goes to cv::imdecode, as every file did before, so the files
// refused and their messages are the same as with cv::imdecode alone.
#include <cstddef>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf {

struct PngDecodeOptions {
  /// Decode plain PNGs with the direct path above; false sends every file to cv::imdecode (the
  /// reference the tests and bench compare with).
  bool direct_path = true;
};

/// Decodes the PNG file bytes `data[0..size)` read from `path` (named in errors). Throws Error naming
/// `path`: "not a PNG file", "truncated PNG (...)", "corrupt PNG (CRC error in ... chunk at byte N)" or
/// "corrupt PNG (cannot be decoded)". Returns the image as cv::imdecode(IMREAD_UNCHANGED) would.
cv::Mat decode_png(const std::string& path, const unsigned char* data, std::size_t size,
                   const PngDecodeOptions& options = {});

/// The zlib stream of the PNG file bytes `data[0..size)`: its IDAT chunks' data joined, after the same
/// chunk walk and CRC checks as decode_png (the same errors). For benchmarks that time libdeflate's
/// inflate alone, the floor under the direct path.
std::vector<unsigned char> png_zlib_stream(const std::string& path, const unsigned char* data, std::size_t size);

/// Reads the whole file at `path` and decodes it as above. Throws Error naming `path` when it is missing,
/// a folder or unreadable, and on the faults above.
cv::Mat read_png_file(const std::string& path, const PngDecodeOptions& options = {});

}  // namespace rdsf
