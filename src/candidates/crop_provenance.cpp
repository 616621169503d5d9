#include "rdsf/candidates/crop_provenance.hpp"

#include <cstdio>
#include <cstdlib>

namespace rdsf {

CropProvenance crop_provenance(const CandidateParams& params) {
  CropProvenance crops;
  crops.window_scale = params.window_scale;
  return crops;
}

std::string crop_provenance_mismatch(const CropProvenance& a, const std::string& a_what, const CropProvenance& b,
                                     const std::string& b_what) {
  if (!a.known() || !b.known()) return "";
  std::string text;
  auto differs = [&](const std::string& name, const std::string& x, const std::string& y) {
    if (x == y) return;
    text += (text.empty() ? "" : "; ") + name + " " + x + " (" + a_what + ") differs from " + y + " (" + b_what + ")";
  };
  auto number = [](double v) {  // the shortest text that reads back as v
    char out[32];
    for (int digits = 6; digits <= 17; ++digits) {
      std::snprintf(out, sizeof out, "%.*g", digits, v);
      if (std::strtod(out, nullptr) == v) break;
    }
    return std::string(out);
  };
  differs("window_box", a.window_box, b.window_box);
  differs("window_scale", number(a.window_scale), number(b.window_scale));
  return text;
}

CropProvenance known_of(const CropProvenance& a, const CropProvenance& b) { return a.known() ? a : b; }

}  // namespace rdsf
