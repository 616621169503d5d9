#include "rdsf/pipeline/model_fit.hpp"

#include "rdsf/candidates/crop_provenance.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/features/feature_spec_record.hpp"

namespace rdsf {

std::string model_fit_problem(const BoostedModel& model, const AnalyserParams& detector) {
  if (model.feature_spec() != detector.features) {
    return feature_spec_mismatch("model feature spec", model.feature_spec(), "the detector's", detector.features);
  }
  const std::string crops = crop_provenance_mismatch(model.training().crops, "the model's training crops",
                                                     crop_provenance(detector.candidates), "the detector's");
  return crops.empty() ? "" : "crops cut differently: " + crops;
}

void check_model_fits(const BoostedModel& model, const AnalyserParams& detector) {
  const std::string problem = model_fit_problem(model, detector);
  if (!problem.empty()) fail(model.path().empty() ? model.name() : model.path(), problem);
}

}  // namespace rdsf
