// OpenCV's image codecs behind rdsf/frame/image_codecs.hpp's table: the module librdsf_image_codecs.so,
// which a shared librdsf opens at their first use, or part of a static librdsf. The library's only
// include of opencv2/imgcodecs.hpp (scripts/include-check.sh).
#include <opencv2/imgcodecs.hpp>

#include "rdsf/frame/image_codecs.hpp"
#include "rdsf/version.hpp"

namespace {

cv::Mat decode(const unsigned char* data, std::size_t size, rdsf::DecodedAs as) {
  const cv::Mat buffer(1, static_cast<int>(size), CV_8U, const_cast<unsigned char*>(data));
  return cv::imdecode(buffer, as == rdsf::DecodedAs::colour ? cv::IMREAD_COLOR : cv::IMREAD_UNCHANGED);
}

bool encode_png(const cv::Mat& image, std::vector<unsigned char>& bytes, int compression_level) {
  if (compression_level == rdsf::kOpenCvDefaultPngParams) return cv::imencode(".png", image, bytes);
  return cv::imencode(".png", image, bytes, {cv::IMWRITE_PNG_COMPRESSION, compression_level});
}

const rdsf::ImageCodecsTable kTable{RDSF_VERSION_STRING, &decode, &encode_png};

}  // namespace

extern "C" const rdsf::ImageCodecsTable* rdsf_image_codecs() { return &kTable; }
