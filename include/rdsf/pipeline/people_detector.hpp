#pragma once
// rdsf::PeopleDetector: the one entry point for a program that links the library (a robot's process, a
// ROS 2 node). Built from a model and parameters, it runs the whole system on each frame:
//   frame -> candidates -> RDSF -> H(x), P(person) -> person when P >= threshold -> tracking -> Detection
//
//   rdsf::PeopleDetector detector("models/people/v2.yml");   // an explicit file: no lookup, no global state
//   for (;;) { rdsf::DepthFrame frame = ...; for (const rdsf::Detection& d : detector.detect(frame)) ...; }
//
// Threading contract: detect() keeps the tracker's state, so call it from one thread at a time with the
// frames in order (it is not re-entrant; distinct detectors are independent). For frames analysed on N
// threads use pipeline() with run_in_frame_order (pipeline/parallel_pipeline.hpp), for a live camera with
// LivePipeline (pipeline/live_pipeline.hpp); detections(frame, result) turns their results into Detections. All
// three give the same detections for the same frames (the parallel one bit for bit).
//
// Bad input throws rdsf::Error with one line: a model file that cannot be read, a model whose feature spec
// differs from params.analyser.features (use params_for(model) to adopt the model's), a frame whose depth
// image is empty or not of its camera model's size.
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/frame/depth_frame.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"

namespace rdsf {

/// One person found in a frame.
struct Detection {
  cv::Rect box;                  ///< pixels: the reported box (params.analyser.reported_box, fitted by default)
  double score = 0;              ///< H(x), the boosted score
  double probability = 0;        ///< P(person), the model's calibration of the score
  int track_id = 0;              ///< tracked person, 1, 2, ... in order of first sight, kept across frames
  /// The box centre at the candidate's layer depth, in the camera frame (pinhole camera model of the
  /// frame: x right, y down, z along the optical axis), metres: z = depth, x = (u - cx) z / fx,
  /// y = (v - cy) z / fy (tracking's centroid_cm, in metres).
  cv::Point3d position_m;
  double distance_walked_m = 0;  ///< path length of this track so far (sum of centroid moves), metres
};

class PeopleDetector {
 public:
  /// Reads the model file at `model_path` (a path; names are not looked up). Throws Error.
  explicit PeopleDetector(const std::string& model_path, PipelineParams params = {});
  explicit PeopleDetector(BoostedModel model, PipelineParams params = {});
  PeopleDetector(PeopleDetector&&) = default;
  PeopleDetector& operator=(PeopleDetector&&) = default;

  /// `params` with the detector's feature spec set to the model's (as rdsf-detect does by default).
  static PipelineParams params_for(const BoostedModel& model, PipelineParams params = {});

  /// The people of the next frame (frames in order, one thread at a time), in candidate order.
  std::vector<Detection> detect(const DepthFrame& frame);

  /// The Detections of `frame`'s result from pipeline() (parallel or live runs). Call it right after that
  /// frame was tracked (in the run's callback): distance_walked_m is the track's length at that moment.
  std::vector<Detection> detections(const DepthFrame& frame, const PipelineFrame& result) const;

  const BoostedModel& model() const { return *model_; }
  const PipelineParams& params() const { return pipeline_->params(); }
  /// The pipeline behind detect(), for run_in_frame_order and LivePipeline.
  PeoplePipeline& pipeline() { return *pipeline_; }

 private:
  std::unique_ptr<BoostedModel> model_;       ///< at a fixed address: the pipeline points to it
  std::unique_ptr<PeoplePipeline> pipeline_;
};

}  // namespace rdsf
