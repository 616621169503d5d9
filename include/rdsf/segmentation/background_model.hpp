#pragma once
// A background model of the room for a static camera (issue 34): per pixel the room's far depth, learned
// from frames, so that whatever stands in front of the room is found even where it shares a depth layer
// with the wall behind it (a person within half a metre of a wall, a cupboard, a chair back). Off unless
// given: the thesis's layers alone are the default and the --thesis preset (docs/candidates.md, "A
// background model of the room").
//
// Learning (BackgroundLearner): per pixel, the m readings (d > 0) it has in the n frames learned from,
// sorted near to far; the background is the reading at rank
//   r = floor(quantile * (m - 1))        (0-based from the nearest)
// and 0 ("never seen") when m = 0. A person walking through covers a pixel in a minority of the frames,
// nearer than the room, so a high quantile skips them (the default 0.8 skips anything nearer in up to
// a fifth of the readings). Missing readings are left out rather than counted as far: the sensor drops
// far walls, edges and dark surfaces in a varying share of frames (half of a synthetic room's pixels
// flicker so), which would otherwise leave them without a background and make every reading there
// foreground. Deterministic: the same frames give the same model whatever their order.
//
// The foreground of a frame (foreground_mask): a pixel with a reading d > 0 is in front of the background
// b when
//   b == 0   or   d + max(M, round(margin_relative * b)) < b        (millimetres, whole numbers)
// with M = round(margin_mm), the relative part computed in steps of 1/65536 ((b * round(margin_relative *
// 65536) + 32768) >> 16). Kinect v1 noise grows with depth squared (about 1.2 mm * z[m]^2 of sigma) and
// 8-bit captures step by 1-3 cm: the relative margin keeps the far wall's noise out, M the near one's.
//
// Stored as a one-frame folder that the PNG frame source reads (rdsf-detect --source DIR shows it):
// DIR/background.depth.png (16-bit, millimetres, 0 = never seen) and DIR/camera.yml (the camera model of
// the frames it was learned from, frame/camera_file.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/core/parameter_table.hpp"
#include "rdsf/frame/camera_model.hpp"
#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/segmentation/depth_layers.hpp"

namespace rdsf {

/// The foreground rule's margins (background_parameters(): --background-margin, --background-relative).
struct BackgroundParams {
  /// A pixel is in front of the background when nearer by more than max(margin_mm, margin_relative * b)
  /// (both rounded to whole millimetres; the rule above).
  double margin_mm = 100.0;
  double margin_relative = 0.03;
};

/// The rows of BackgroundParams (core/parameter_table.hpp): margin_mm in [0, 10000], margin_relative in
/// [0, 1]. No thesis values: the stage runs only when a background is given, and --thesis gives none.
const ParameterTable<BackgroundParams>& background_parameters();

struct BackgroundModel {
  static constexpr const char* kDepthFileName = "background.depth.png";

  cv::Mat1w far_mm;     ///< per pixel the room's depth (mm), 0 = never seen; the camera's size
  CameraModel camera;   ///< of the frames it was learned from
  std::string path;     ///< the folder it was read from (names it in errors), or empty

  /// Throws Error (one line naming the background's folder and the frame) when `frame` is not of the size
  /// and camera model the background was learned from.
  void check_fits(const DepthFrame& frame) const;
};

/// 255 where `depth_mm` is in front of `background` (the rule above), else 0. Sizes must agree.
cv::Mat1b foreground_mask(const cv::Mat1w& depth_mm, const cv::Mat1w& background_mm, const BackgroundParams& params);

/// `segmentation` (of a frame whose depth is `depth_mm`) restricted to the pixels in front of
/// `background_mm` (the rule above; foreground_mask() without making the mask): every other pixel's label
/// set to 0, and each layer's mean, nearest and farthest depth and pixel count taken over its remaining
/// pixels (a layer left without pixels keeps its own, with pixel_count 0). The candidate finder then shapes
/// what stands in front of the room as the layer's objects. Sizes must agree.
Segmentation in_front_of(const Segmentation& segmentation, const cv::Mat1w& depth_mm, const cv::Mat1w& background_mm,
                         const BackgroundParams& params);

/// Learns a background from frames added one by one (at most `max_frames` are kept: the caller samples
/// its source evenly, see evenly_spaced()).
class BackgroundLearner {
 public:
  /// `quantile` in [0, 1] (the rule above).
  explicit BackgroundLearner(double quantile = 0.8);

  /// Adds a frame; the first one fixes the size and camera model, a frame of another size or camera
  /// model throws Error naming it.
  void add(const DepthFrame& frame);
  std::size_t frames() const { return frames_.size(); }
  /// The depth images added, in order.
  const std::vector<cv::Mat1w>& depths_mm() const { return frames_; }

  /// The background of the frames added (Error when none was).
  BackgroundModel model() const;

 private:
  double quantile_;
  CameraModel camera_;
  std::string first_name_;
  std::vector<cv::Mat1w> frames_;
};

/// `count` frame indices of a source of `total` frames, spread evenly: round(i * (total - 1) / (count - 1))
/// for i = 0..count-1 (all of them when count >= total).
std::vector<std::int64_t> evenly_spaced(std::int64_t total, std::int64_t count);

/// Writes `model` into the folder `dir` (created when missing): background.depth.png and camera.yml, each
/// durably (temporary name, sync, rename). An existing background there is replaced only with `overwrite`
/// (else Error "already exists").
void write_background(const std::string& dir, const BackgroundModel& model, bool overwrite);

/// Reads the folder `dir` written by write_background (Error naming the file when it is missing or bad, or
/// when the image's size is not its camera model's).
BackgroundModel read_background(const std::string& dir);

}  // namespace rdsf
