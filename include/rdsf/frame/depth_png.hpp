#pragma once
// Reading and writing the on-disk image formats of the workbench, with the checks that turn bad files into
// one-line errors: depth is a 16-bit single-channel PNG in millimetres, colour an 8-bit PNG.
#include <string>

#include <opencv2/core.hpp>

namespace rdsf {

/// Reads a 16-bit single-channel PNG of depth in millimetres. Throws Error naming `path` when the file is
/// missing, is not a PNG, is corrupt or truncated, or is 8-bit or colour.
cv::Mat1w read_depth_png(const std::string& path);

/// Reads an 8-bit colour (or grey) PNG as BGR. Throws Error naming `path` on the same faults, and when
/// `expected` is non-empty and the size differs from it.
cv::Mat3b read_colour_png(const std::string& path, cv::Size expected = {});

/// Writes `image` as PNG through a temporary file and a rename, so a killed writer never leaves a
/// half-written file under the final name. Throws Error naming `path` on failure.
void write_png_atomically(const std::string& path, const cv::Mat& image);

}  // namespace rdsf
