#pragma once
// The frame analyser shared by every program (the thesis's frame analyser before the classifier): it makes
// candidates and their features, not detections (those come from PeoplePipeline):
//   depth frame -> segmentation (depth layers) -> candidates (boxes, 64x128 crops) -> RDSF features
// Classification and tracking build on its output.
#include <memory>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/candidates/candidate.hpp"
#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/analysis/stage_times.hpp"
#include "rdsf/candidates/candidate_params.hpp"
#include "rdsf/features/feature_spec.hpp"
#include "rdsf/features/rdsf_extractor.hpp"
#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/segmentation/background_model.hpp"
#include "rdsf/segmentation/depth_layers.hpp"
#include "rdsf/segmentation/segmentation_params.hpp"

namespace rdsf {

struct AnalyserParams {
  SegmentationParams segmentation;
  CandidateParams candidates;
  FeatureSpec features;
  /// The box detections, CSVs, pictures, tracking and the evaluation report (the crop always comes from
  /// the strict box's window). The thesis reports the strict box.
  BoxKind reported_box = BoxKind::fitted;
  /// The few parameters counted in pixels (segmentation row_step and n, candidates k and column_gap) are
  /// stated for a camera of this focal length (the Kinect v1 at 640x480); a frame whose camera model has
  /// other focal lengths gets them scaled by fx / reference (n, column_gap: along rows) and fy / reference
  /// (row_step, k: along columns), rounded, at least 1, so that they span the same angle (issue 36: other
  /// resolutions and sensors). 0: pixel counts as given, whatever the camera.
  double reference_focal_px = 525.0;
  /// A background model of the room, for a static camera (segmentation/background_model.hpp): when set,
  /// the objects in front of it are added as candidates beside the layers' (foreground_candidates.hpp).
  /// Null: off (the default; --thesis sets none). Shared and never changed, so analyse() stays const and
  /// thread-safe. A frame of another size or camera model than the background's is an Error.
  std::shared_ptr<const BackgroundModel> background;
  /// The foreground rule's margins (with a background, or with local_front_reach_cm).
  BackgroundParams background_margins;
  /// Without a background model: the objects in front of their surroundings along each row within this
  /// reach (cm; segmentation/local_background.hpp) are added as candidates beside the layers', as a
  /// background's are. 0: off (the default and the thesis's).
  double local_front_reach_cm = 0.0;
};

/// The table of AnalyserParams: the segmentation's and candidates' rows, then the reported box
/// (core/parameter_table.hpp). The feature spec has its own parser (FeatureSpec::parse).
const ParameterTable<AnalyserParams>& analyser_parameters();

/// `params` with its pixel counts scaled to `camera` (see AnalyserParams::reference_focal_px); the same
/// params for a camera of the reference focal length.
AnalyserParams params_for_camera(const AnalyserParams& params, const CameraModel& camera);

/// `params` with every departure from the thesis turned off (docs/frame-analyser.md, "Departures from the thesis"): no
/// left-border jump, no occlusion gaps, no floor trimming, no fitted reach, no joining of pieces, no
/// splitting. Everything else (the thesis's own parameters) is kept.
AnalyserParams thesis_params(AnalyserParams params = {});

struct FrameAnalysis {
  Segmentation segmentation;
  /// With a background model: the segmentation restricted to the pixels in front of it (in_front_of()),
  /// the labels the candidates with Candidate::foreground were cut from; else empty.
  Segmentation in_front;
  std::vector<Candidate> candidates;
  cv::Mat1f features;  ///< one row of RDSF values per candidate (empty when not asked for)
  StageTimes times;  ///< segmentation, candidates and features (the classifier and tracking stay 0)
};

class FrameAnalyser {
 public:
  explicit FrameAnalyser(AnalyserParams params = {});

  const AnalyserParams& params() const { return params_; }
  const RdsfExtractor& extractor() const { return extractor_; }

  /// Segments the frame and shapes its candidates; with `with_features`, also computes their RDSF. With
  /// CropColour::later the candidates' colour crops are left empty (cut_colour_crop() cuts one later).
  FrameAnalysis analyse(const DepthFrame& frame, bool with_features = true,
                        CropColour colour = CropColour::cut) const;

  /// RDSF rows for the given candidates (candidates.size() x dimension()).
  cv::Mat1f features(const std::vector<Candidate>& candidates) const;

 private:
  AnalyserParams params_;
  RdsfExtractor extractor_;
};

}  // namespace rdsf
