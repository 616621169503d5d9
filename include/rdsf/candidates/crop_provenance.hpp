#pragma once
// How a candidate's crops were cut, beyond the feature spec: the spec already fixes the crop size and its
// sampling ("window=64x128 ... crop=nearest-masked"); this records the rest of what changes a crop's
// pixels for the same object:
//   window_box    the box the window is built on: always the strict box (BoxKind only changes the box that
//                 detections report, never the crop), recorded so that another choice is never silent
//   window_scale  window = window_box enlarged by this factor about its centre (CandidateParams)
// Sample-set manifests and model files (format 3) record it; a model runs only on crops cut the way its
// training crops were (pipeline/model_fit.hpp). Files written before it was recorded have an unknown
// provenance (window_scale 0), which agrees with any.
#include <string>

#include "rdsf/candidates/candidate_params.hpp"

namespace rdsf {

struct CropProvenance {
  std::string window_box = "strict";
  double window_scale = 0.0;  ///< 0 = not recorded (an older file, or samples without crops)

  bool known() const { return window_scale > 0.0; }
  bool operator==(const CropProvenance& other) const {
    return window_box == other.window_box && window_scale == other.window_scale;
  }
  bool operator!=(const CropProvenance& other) const { return !(*this == other); }
};

/// The provenance of the crops `params` cut.
CropProvenance crop_provenance(const CandidateParams& params);

/// Empty when `a` and `b` agree or either is unknown; else one line naming every parameter that differs,
/// e.g. "window_scale 1.25 (the model's training crops) differs from 1.5 (the detector's)".
std::string crop_provenance_mismatch(const CropProvenance& a, const std::string& a_what, const CropProvenance& b,
                                     const std::string& b_what);

/// The known one of two agreeing provenances (`a` when both are known or both unknown).
CropProvenance known_of(const CropProvenance& a, const CropProvenance& b);

}  // namespace rdsf
