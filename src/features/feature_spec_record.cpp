#include "rdsf/features/feature_spec_record.hpp"

#include "rdsf/core/error.hpp"

namespace rdsf {

FeatureSpecNumbers feature_spec_numbers(const FeatureSpec& spec) {
  FeatureSpecNumbers out = {{"window_width_px", spec.window_width_px}, {"window_height_px", spec.window_height_px}};
  if (spec.layout == FeatureSpec::Layout::Cells) {
    out.emplace_back("cell_px", spec.cell_px);
  } else {
    out.emplace_back("rect_min_px", spec.rect_min_px);
    out.emplace_back("rect_max_px", spec.rect_max_px);
    out.emplace_back("rect_step_px", spec.rect_step_px);
    out.emplace_back("rect_stride_px", spec.rect_stride_px);
  }
  out.emplace_back("bin_width_mm", spec.bin_width_mm);
  out.emplace_back("max_depth_mm", spec.max_depth_mm);
  return out;
}

FeatureSpec feature_spec_from_record(const std::string& canonical, const std::string& hash,
                                     const FeatureSpecNumbers& numbers) {
  const FeatureSpec spec = FeatureSpec::from_canonical(canonical);
  if (hash != spec.hash()) {
    throw Error("feature spec '" + canonical + "' has hash " + spec.hash() + ", the file says " + hash +
                " (damaged file?)");
  }
  const FeatureSpecNumbers expected = feature_spec_numbers(spec);
  for (const auto& [key, value] : numbers) {
    bool known = false;
    for (const auto& [want_key, want] : expected) {
      if (key != want_key) continue;
      known = true;
      if (value != want) {
        throw Error("feature spec number " + key + " = " + std::to_string(value) + " but its canonical text '" +
                    canonical + "' says " + std::to_string(want) + " (damaged file?)");
      }
    }
    if (!known) {
      throw Error("feature spec number " + key + " does not belong to '" + canonical + "' (damaged file?)");
    }
  }
  return spec;
}

std::string feature_spec_mismatch(const std::string& found_what, const FeatureSpec& found,
                                  const std::string& wanted_what, const FeatureSpec& wanted) {
  return found_what + " '" + found.canonical() + "' (hash " + found.hash() + ") differs from " + wanted_what +
         " '" + wanted.canonical() + "' (hash " + wanted.hash() + ")";
}

}  // namespace rdsf
