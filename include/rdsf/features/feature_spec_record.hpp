#pragma once
// A feature spec as sample sets and model files record it: the canonical text (the authority), its hash,
// and the spec's numbers beside them for people and older readers. Reading accepts every spec this build
// knows (FeatureSpec::from_canonical) and refuses unknown texts and records whose hash or numbers disagree.
#include <string>
#include <utility>
#include <vector>

#include "rdsf/features/feature_spec.hpp"

namespace rdsf {

using FeatureSpecNumbers = std::vector<std::pair<std::string, int>>;

/// The numbers written beside the text: window_width_px, window_height_px, then cell_px ("rdsf") or
/// rect_min_px, rect_max_px, rect_step_px, rect_stride_px ("rdsf-rect"), then bin_width_mm, max_depth_mm.
FeatureSpecNumbers feature_spec_numbers(const FeatureSpec& spec);

/// The spec a file records. `numbers` holds those of the keys above that the file gives (all optional).
/// Throws Error with a one-line message (without the file's name: the caller adds it).
FeatureSpec feature_spec_from_record(const std::string& canonical, const std::string& hash,
                                     const FeatureSpecNumbers& numbers);

/// The one-line complaint when `found` (of a model, a sample set) is not `wanted` (of a detector, a set):
/// "<found_what> '<canonical>' (hash H) differs from <wanted_what> '<canonical>' (hash H)".
std::string feature_spec_mismatch(const std::string& found_what, const FeatureSpec& found,
                                  const std::string& wanted_what, const FeatureSpec& wanted);

}  // namespace rdsf
