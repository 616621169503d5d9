#include "rdsf/dataset/crop_augmentation.hpp"

#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

#include "rdsf/core/error.hpp"
#include "rdsf/core/stable_hash.hpp"

namespace rdsf {
namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) {
  // 53 random bits -> [0, 1): the same on every standard library (unlike std::uniform_real_distribution).
  const double u = static_cast<double>(rng() >> 11) * (1.0 / 9007199254740992.0);
  return lo + (hi - lo) * u;
}

}  // namespace

void CropAugmentation::validate() const {
  if (copies < 0 || copies > 16) throw Error("augmentation copies must be 0-16 (" + std::to_string(copies) + " given)");
  if (!(max_shift >= 0.0 && max_shift <= 0.15)) {
    throw Error("augmentation shift " + std::to_string(max_shift) + " is outside 0-0.15 of the window (it would move the person out of it)");
  }
  if (!(max_scale >= 0.0 && max_scale <= 0.15)) {
    throw Error("augmentation scale " + std::to_string(max_scale) + " is outside 0-0.15 (it would cut the person or leave the window)");
  }
  if (!(occlusion >= 0.0 && occlusion <= 1.0)) throw Error("augmentation occlusion probability must be in [0, 1]");
  if (!(max_occluded > 0.0 && max_occluded <= 0.5)) throw Error("augmentation occluded fraction must be in (0, 0.5]");
  if (copies > 0 && max_shift == 0.0 && max_scale == 0.0 && occlusion == 0.0) {
    throw Error("augmentation copies need shift, scale or occlusion (else they repeat the crop)");
  }
}

std::string CropAugmentation::describe() const {
  if (!enabled()) return "off";
  std::ostringstream out;
  out << (mirror ? "mirror" : "no mirror");
  if (copies > 0) {
    char text[160];
    std::snprintf(text, sizeof text, ", %d copies (shift %g, scale %g, occlusion %g)", copies, max_shift, max_scale,
                  occlusion);
    out << text;
  }
  out << ", seed " << seed;
  return out.str();
}

CropAugmentation parse_augmentation(const std::string& text, int copies, std::uint64_t seed) {
  CropAugmentation a;
  a.seed = seed;
  if (text.empty() || text == "off") {
    if (copies > 0) throw Error("--augment-copies needs --augment shift, scale or occlusion");
    return a;
  }
  std::stringstream words(text);
  std::string word;
  while (std::getline(words, word, ',')) {
    if (word == "mirror") {
      a.mirror = true;
    } else if (word == "shift") {
      a.max_shift = 0.05;
    } else if (word == "scale") {
      a.max_scale = 0.05;
    } else if (word == "occlusion") {
      a.occlusion = 0.3;
    } else {
      throw Error("augmentation '" + word + "' is not known (off, or a list of mirror, shift, scale, occlusion)");
    }
  }
  a.copies = copies;
  a.validate();
  return a;
}

cv::Mat1w mirrored_crop(const cv::Mat1w& crop) {
  cv::Mat1w out(crop.size());
  for (int y = 0; y < crop.rows; ++y) {
    for (int x = 0; x < crop.cols; ++x) out(y, x) = crop(y, crop.cols - 1 - x);
  }
  return out;
}

cv::Mat1w shifted_scaled_crop(const cv::Mat1w& crop, double dx_px, double dy_px, double scale) {
  if (!(scale > 0.0)) throw Error("crop scale must be positive");
  cv::Mat1w out(crop.size(), 0);
  const double cx = (crop.cols - 1) / 2.0, cy = (crop.rows - 1) / 2.0;
  for (int y = 0; y < crop.rows; ++y) {
    const int sy = static_cast<int>(std::lround(cy + (y - cy) / scale - dy_px));
    if (sy < 0 || sy >= crop.rows) continue;
    for (int x = 0; x < crop.cols; ++x) {
      const int sx = static_cast<int>(std::lround(cx + (x - cx) / scale - dx_px));
      if (sx >= 0 && sx < crop.cols) out(y, x) = crop(sy, sx);
    }
  }
  return out;
}

cv::Mat1w occluded_crop(const cv::Mat1w& crop, const cv::Rect& band) {
  cv::Mat1w out = crop.clone();
  const cv::Rect r = band & cv::Rect(0, 0, crop.cols, crop.rows);
  if (r.area() > 0) out(r).setTo(0);
  return out;
}

std::vector<cv::Mat1w> augmented_crops(const cv::Mat1w& crop, const CropAugmentation& a, std::int64_t sample_id) {
  std::vector<cv::Mat1w> out;
  if (a.mirror) out.push_back(mirrored_crop(crop));
  std::mt19937_64 rng(a.seed ^ fnv1a64("augment:" + std::to_string(sample_id)));
  for (int c = 0; c < a.copies; ++c) {
    // Every draw is made whatever is enabled, so enabling one kind does not change the others' values.
    const double dx = uniform(rng, -a.max_shift, a.max_shift) * crop.cols;
    const double dy = uniform(rng, -a.max_shift, a.max_shift) * crop.rows;
    const double s = 1.0 + uniform(rng, -a.max_scale, a.max_scale);
    const bool occlude = uniform(rng, 0.0, 1.0) < a.occlusion;
    const bool bottom = uniform(rng, 0.0, 1.0) < 0.5, left = uniform(rng, 0.0, 1.0) < 0.5;
    const double amount = uniform(rng, 0.1, a.max_occluded);
    const bool flip = a.mirror && uniform(rng, 0.0, 1.0) < 0.5;
    cv::Mat1w v = shifted_scaled_crop(flip ? mirrored_crop(crop) : crop, dx, dy, s);
    if (occlude) {
      const int h = static_cast<int>(std::lround(amount * crop.rows)), w = static_cast<int>(std::lround(amount * crop.cols));
      const cv::Rect band = bottom ? cv::Rect(0, crop.rows - h, crop.cols, h)
                                   : cv::Rect(left ? 0 : crop.cols - w, 0, w, crop.rows);
      v = occluded_crop(v, band);
    }
    out.push_back(v);
  }
  return out;
}

}  // namespace rdsf
