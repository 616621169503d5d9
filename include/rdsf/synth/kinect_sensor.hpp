#pragma once
// A model of the Kinect v1 (PrimeSense PS1080) depth sensor applied to an ideal rendering:
//  - range: no reading (0) nearer than 0.5 m or farther than 8 m;
//  - projector shadow: the IR projector sits baseline_m to the right of the IR camera, so the background
//    just left of every near object is not lit by the pattern and has no reading (band width
//    fx * baseline * (1/z_near - 1/z_far) pixels);
//  - noise and quantisation growing with the square of the distance: Gaussian noise of sigma
//    noise_per_m2 * z^2, then depth quantised in disparity steps (z = disparity_scale / k), i.e. steps of
//    z^2 / disparity_scale (2.9 mm at 1 m, 4.6 cm at 4 m);
//  - ragged depth edges: far-side edge pixels are lost or take the near depth (the near surface spreads
//    over the edge, as with block matching); missing readings in blobby patches on dark or
//    shiny materials and surfaces seen at a grazing angle (a smooth random field thresholded by the
//    surface's dropout), and on glass (windows);
//  - the band without readings at the image border left by depth-to-colour registration;
//  - per clip, a capture profile (SensorProfile): Xtion-like sensors with stronger noise, half of it
//    spatially correlated (blocks of a few pixels move together), and captures stored as 8 bits with a
//    linear scale, as the real frames of ../shared/realdata were: depth_mm = offset + step * v, v in 1..255,
//    with steps of 12-28 mm (readings outside the 255 steps are lost), on top of the disparity steps.
// Defaults reproduce the statistics measured on ../shared/realdata (see docs/rdsf-synth.md).
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "rdsf/frame/camera_model.hpp"
#include "rdsf/synth/renderer.hpp"
#include "rdsf/synth/scene.hpp"

namespace rdsf::synth {

struct KinectSensorParams {
  double min_range_m = 0.5;
  double max_range_m = 8.0;
  double baseline_m = 0.075;       ///< IR projector to IR camera
  double disparity_scale = 348.0;  ///< 8 sub-pixel steps * 580 px (IR focal length) * 0.075 m
  double noise_per_m2 = 0.0012;    ///< depth noise sigma = noise_per_m2 * z^2 (metres)
  double edge_far_hole = 0.3;      ///< probability of losing a pixel on the far side of a depth edge
  double edge_near_hole = 0.1;     ///< ... on the near side
  double edge_fatten = 0.35;       ///< probability that a far-side edge pixel takes the near depth
  double edge_jump = 0.05;         ///< a depth edge: neighbours differ by more than this fraction of z
  int patch_cell_px = 10;          ///< scale of the blobby dropout field (at 640 px wide; 20 before issue 13)
  double grazing_cosine = 0.3;     ///< surfaces seen at a cosine below this lose readings increasingly
  double base_dropout = 0.0;       ///< dropout of every surface in addition to its material's
  /// Block matching's coherence: the Kinect correlates windows of about 9x9 pixels, so its holes are
  /// blobs, not specks. After the per-pixel model, along rows and then columns, a hole of at most this
  /// many pixels between two readings of one surface (depths within edge_jump of each other) takes their
  /// readings, and a run of at most this many readings between holes is lost. 0: per-pixel holes only.
  int coherent_holes_px = 0;
  /// Border band without readings (registration), in pixels at 640x480; scaled with the image.
  int band_left_px = 18, band_right_px = 30, band_top_px = 20, band_bottom_px = 8;
  double eight_bit_share = 0.5;  ///< share of clips stored as 8-bit linear captures
  double eight_bit_step_min_mm = 12, eight_bit_step_max_mm = 28;
  double eight_bit_offset_min_m = 0.4, eight_bit_offset_max_m = 1.0;  ///< depth of code 0
  double xtion_share = 0.3;  ///< share of clips with Xtion-like noise
  double xtion_noise_min = 1.3, xtion_noise_max = 2.0;  ///< noise factor of those clips
};

/// How one clip is captured (drawn per clip by draw_profile).
struct SensorProfile {
  double noise_factor = 1.0;        ///< on noise_per_m2
  double correlated_share = 0.0;    ///< part of the noise that is shared by neighbouring pixels (0..1)
  double eight_bit_step_mm = 0;     ///< 0: full 16-bit millimetres; otherwise the 8-bit step
  double eight_bit_offset_mm = 0;   ///< depth of code 0 of the 8-bit capture
};

class KinectSensor {
 public:
  KinectSensor(const CameraModel& camera, KinectSensorParams params = {});
  const KinectSensorParams& params() const { return params_; }

  /// The depth image (mm, 0 = no reading) the sensor delivers for `buffers` rendered from `scene`;
  /// `seed` drives its noise (same seed, same image).
  cv::Mat1w measure(const Scene& scene, const RenderBuffers& buffers, std::uint64_t seed,
                    const SensorProfile& profile = {}) const;

  /// A clip's capture profile drawn from the shares and ranges of the parameters.
  SensorProfile draw_profile(Rng& rng) const;

  /// Block matching's coherence (KinectSensorParams::coherent_holes_px), in place: along every row and
  /// then every column, a hole of at most `max_px` pixels between two readings whose depths differ by at
  /// most `jump_fraction` of the smaller takes the nearer end's reading (8-bit steps stay steps); then a
  /// run of at most `max_px` readings between holes (the image's end counts as one) is lost.
  static void make_holes_coherent(cv::Mat1w& depth_mm, int max_px, double jump_fraction);

  /// True when pixel (x, y) lies in the registration band (never has a reading).
  bool in_band(int x, int y) const;

 private:
  struct PixelModel;  // measure()'s model of one pixel's reading (kinect_sensor.cpp)
  CameraModel camera_;
  KinectSensorParams params_;
  int band_left_, band_right_, band_top_, band_bottom_;
};

}  // namespace rdsf::synth
