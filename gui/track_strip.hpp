#pragma once
// A track as a strip of crops (rdsf-label --per-track): the depth crops of the candidates one answer would
// label, in frame order, at most `max_crops` of them evenly spaced (first and last always), each with its
// frame name below; the one asked (`asked`, an index into `crops`) framed in the highlight colour.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf::gui {

struct StripCrop {
  cv::Mat1w depth_crop_mm;  ///< the candidate's masked depth crop (64x128)
  std::string frame;        ///< its frame's name
};

/// The strip, `width_px` wide (crops shrink to fit), with `title` above it.
cv::Mat3b render_track_strip(const std::vector<StripCrop>& crops, std::size_t asked, const std::string& title,
                             int width_px, std::size_t max_crops = 12);

}  // namespace rdsf::gui
