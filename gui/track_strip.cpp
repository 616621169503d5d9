#include "gui/track_strip.hpp"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "gui/screen_text.hpp"
#include "rdsf/analysis/overlay.hpp"

namespace rdsf::gui {

cv::Mat3b render_track_strip(const std::vector<StripCrop>& crops, std::size_t asked, const std::string& title,
                             int width_px, std::size_t max_crops) {
  constexpr int kMargin = 16, kTitle = 30, kCaption = 22, kGap = 6;
  // Which crops: all, or max_crops evenly spaced with the first, the last and the asked one among them.
  std::vector<std::size_t> shown;
  const std::size_t n = crops.size();
  if (n <= max_crops || max_crops < 3) {
    for (std::size_t i = 0; i < n; ++i) shown.push_back(i);
  } else {
    for (std::size_t k = 0; k < max_crops; ++k) shown.push_back(k * (n - 1) / (max_crops - 1));
    if (asked < n && std::find(shown.begin(), shown.end(), asked) == shown.end()) {
      std::size_t nearest = 1;  // the asked crop replaces the nearest inner one
      for (std::size_t k = 1; k + 1 < shown.size(); ++k) {
        const auto distance = [&](std::size_t j) { return shown[j] > asked ? shown[j] - asked : asked - shown[j]; };
        if (distance(k) < distance(nearest)) nearest = k;
      }
      shown[nearest] = asked;
    }
  }
  const int count = std::max<int>(1, static_cast<int>(shown.size()));
  const int cell_w = std::min(96, (width_px - 2 * kMargin) / count - kGap);
  const int cell_h = cell_w * 2;
  cv::Mat3b strip(kTitle + cell_h + kCaption + kMargin, width_px);
  strip.setTo(kBackground);
  put(strip, title, {kMargin, 20}, 0.5, kText);
  for (std::size_t k = 0; k < shown.size(); ++k) {
    const StripCrop& c = crops[shown[k]];
    const int x = kMargin + static_cast<int>(k) * (cell_w + kGap);
    cv::Mat3b crop = colourise_depth(c.depth_crop_mm);
    cv::resize(crop, crop, {cell_w, cell_h}, 0, 0, cv::INTER_AREA);
    crop.copyTo(strip(cv::Rect(x, kTitle, cell_w, cell_h)));
    const bool is_asked = shown[k] == asked;
    if (is_asked) cv::rectangle(strip, cv::Rect(x - 2, kTitle - 2, cell_w + 4, cell_h + 4), kHighlight, 2);
    std::string name = c.frame.size() > 8 ? c.frame.substr(c.frame.size() - 8) : c.frame;
    put(strip, name, {x, kTitle + cell_h + 16}, 0.35, is_asked ? kHighlight : kDim);
  }
  return strip;
}

}  // namespace rdsf::gui
