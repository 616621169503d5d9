#include "rdsf/pipeline/people_detector.hpp"

#include "rdsf/classifier/model_file.hpp"

namespace rdsf {

PeopleDetector::PeopleDetector(const std::string& model_path, PipelineParams params)
    : PeopleDetector(read_model_file(model_path), std::move(params)) {}

PeopleDetector::PeopleDetector(BoostedModel model, PipelineParams params)
    : model_(std::make_unique<BoostedModel>(std::move(model))),
      pipeline_(std::make_unique<PeoplePipeline>(std::move(params), model_.get())) {}

PipelineParams PeopleDetector::params_for(const BoostedModel& model, PipelineParams params) {
  params.analyser.features = model.feature_spec();
  return params;
}

std::vector<Detection> PeopleDetector::detect(const DepthFrame& frame) { return detections(frame, pipeline_->process(frame)); }

std::vector<Detection> PeopleDetector::detections(const DepthFrame& frame, const PipelineFrame& result) const {
  std::vector<Detection> out;
  const BoxKind box = pipeline_->params().analyser.reported_box;
  for (std::size_t i = 0; i < result.person.size(); ++i) {
    if (result.person[i] == 0) continue;
    const TrackedPerson* person = pipeline_->tracker().person(result.person[i]);
    Detection d;
    const Candidate& c = result.analysis.candidates[i];
    d.box = reported_box(c, box);
    d.score = result.scores[i];
    d.probability = result.probabilities[i];
    d.track_id = result.person[i];
    d.position_m = centroid_cm(d.box, c.layer_depth_mm, frame.camera) / 100.0;  // what the tracker matched
    if (person != nullptr) d.distance_walked_m = person->distance_cm / 100.0;
    out.push_back(d);
  }
  return out;
}

}  // namespace rdsf
