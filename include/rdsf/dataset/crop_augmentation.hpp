#pragma once
// More positives from the same crops, at training time (the stored samples are never changed).
//
// A crop is the window's masked depth (64x128, 0 = no reading or another layer). Variants:
//   - mirror: out(x, y) = in(W - 1 - x, y), exact;
//   - shift and scale of the window: out(x, y) = in(cx + (x - cx) / s - dx, cy + (y - cy) / s - dy) by
//     nearest neighbour about the crop's centre (cx, cy) = ((W - 1) / 2, (H - 1) / 2); what falls outside
//     the crop reads 0, as beyond the image border;
//   - occlusion: a band of the crop is set to 0, as when something in front of the person is cut away by
//     the layer mask (a table before the legs: the bottom band; a person or a door post beside: a side band).
// Each positive gets its mirror (when `mirror`) and `copies` random variants (shift, scale, occlusion as
// enabled), drawn from a std::mt19937_64 seeded with `seed` and the sample's id: the same seed gives the
// same crops everywhere.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace rdsf {

struct CropAugmentation {
  bool mirror = false;           ///< add the mirrored crop
  int copies = 0;                ///< random variants per positive (0-16)
  double max_shift = 0.0;        ///< of the window's width / height, uniform in +-max_shift (0-0.15)
  double max_scale = 0.0;        ///< relative, scale uniform in [1 - max_scale, 1 + max_scale] (0-0.15)
  double occlusion = 0.0;        ///< probability that a variant gets an occluding band (0-1)
  double max_occluded = 0.35;    ///< largest fraction of the crop's height (bottom band) or width (side band)
  std::uint64_t seed = 1;

  /// Variants augmented_crops() makes of each positive: the mirror (when on) and the copies.
  int variants_per_crop() const { return (mirror ? 1 : 0) + copies; }
  bool enabled() const { return mirror || copies > 0; }
  /// Throws Error naming the parameter when a value would leave the window or makes no sense.
  void validate() const;
  /// "mirror, 2 copies (shift 0.05, scale 0.05, occlusion 0.3)" or "off".
  std::string describe() const;
};

/// Parses "--augment" text: "off", or a comma list of mirror, shift, scale, occlusion (default amounts:
/// shift 0.05, scale 0.05, occlusion 0.3; copies is separate). Throws Error on an unknown word.
CropAugmentation parse_augmentation(const std::string& text, int copies, std::uint64_t seed);

cv::Mat1w mirrored_crop(const cv::Mat1w& crop);
/// Shifted by (dx_px, dy_px) and scaled by `scale` about the centre (formula above).
cv::Mat1w shifted_scaled_crop(const cv::Mat1w& crop, double dx_px, double dy_px, double scale);
/// `band` set to 0 (clipped to the crop).
cv::Mat1w occluded_crop(const cv::Mat1w& crop, const cv::Rect& band);

/// The variants of one positive (not the crop itself), in a fixed order: mirror first, then the copies.
std::vector<cv::Mat1w> augmented_crops(const cv::Mat1w& crop, const CropAugmentation& a, std::int64_t sample_id);

}  // namespace rdsf
