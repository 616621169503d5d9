#pragma once
// OpenCV's image codecs (cv::imdecode, cv::imencode of libopencv_imgcodecs), loaded at their first use.
//
// The library decodes and encodes plain PNGs itself (png_decoder.hpp, png_encoder.hpp); OpenCV's codecs are
// its reference and fallback: PNGs outside the direct paths, compressed colour images of bags (JPEG), the
// default-parameter PNGs of write_png_atomically. Linking libopencv_imgcodecs brings in about 130 more shared
// libraries (GDAL, GDCM, OpenEXR, HDF5, ...), whose loading and relocation was most of a program's start:
// about 170 of its 200 ms on this project's machine, paid by every run of every program, 30 ms without
// them (docs/performance.md, "Program start"). So a shared librdsf does not link them: the two functions
// below call through the module librdsf_image_codecs.so, which links them and sits beside librdsf (the build
// tree's and the installed library's folder alike), opened the first time one is called (thread-safe, once
// per process). A static librdsf links OpenCV's codecs and calls them directly.
//
// Both behave as the OpenCV calls named (the same images, the same bytes, the same cv::Exception). A module
// that is missing or of another version is an Error naming its path and the problem.
#include <cstddef>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf {

enum class DecodedAs {
  unchanged,  ///< cv::IMREAD_UNCHANGED: the file's depth and channels (BGR(A) order)
  colour,     ///< cv::IMREAD_COLOR: 8-bit BGR
};

/// cv::imdecode of the file bytes `data[0..size)`: an empty image when OpenCV cannot decode them.
cv::Mat opencv_decode_image(const unsigned char* data, std::size_t size, DecodedAs as);

/// cv::imencode(".png", image, bytes, params) with params {cv::IMWRITE_PNG_COMPRESSION, compression_level}
/// for a level of 0..9, and no params (OpenCV's default: the Sub filter, level 1, RLE strategy) for
/// kOpenCvDefaultPngParams. False when OpenCV cannot encode the image.
constexpr int kOpenCvDefaultPngParams = -1;
bool opencv_encode_png(const cv::Mat& image, std::vector<unsigned char>& bytes, int compression_level);

/// Opens OpenCV's codecs now (nothing when they are open or linked): a live program that will need them
/// (the ROS node on compressed topics) pays their loading (about 150 ms) at its start, not at a frame.
void open_image_codecs();

/// The file OpenCV's codecs are called through: the module's path, or "" with a static librdsf.
std::string image_codecs_module_path();

/// What the module gives librdsf (src/frame/image_codecs_module.cpp; not for callers): its C entry
/// rdsf_image_codecs() returns this table, whose version is the RDSF_VERSION_STRING of the librdsf it was
/// built with (a module of another version is refused).
struct ImageCodecsTable {
  const char* version;
  cv::Mat (*decode)(const unsigned char* data, std::size_t size, DecodedAs as);
  bool (*encode_png)(const cv::Mat& image, std::vector<unsigned char>& bytes, int compression_level);
};

}  // namespace rdsf

extern "C" const rdsf::ImageCodecsTable* rdsf_image_codecs();
