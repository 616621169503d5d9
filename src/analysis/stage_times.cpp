#include "rdsf/analysis/stage_times.hpp"

namespace rdsf {

StageTimes& StageTimes::operator+=(const StageTimes& o) {
  segmentation_ms += o.segmentation_ms;
  candidates_ms += o.candidates_ms;
  features_ms += o.features_ms;
  classifier_ms += o.classifier_ms;
  tracking_ms += o.tracking_ms;
  return *this;
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace rdsf
