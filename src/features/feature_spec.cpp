#include "rdsf/features/feature_spec.hpp"

#include <charconv>
#include <map>
#include <regex>
#include <vector>

#include "rdsf/core/error.hpp"
#include "rdsf/core/stable_hash.hpp"

namespace rdsf {
namespace {

std::string str(int value) { return std::to_string(value); }

std::string known_text() { return "rdsf or rdsf-rect"; }

// Squares of one side at every position of the stride grid that keeps them inside the window.
int positions(int window, int side, int stride) { return side > window ? 0 : (window - side) / stride + 1; }

int parse_number(const std::string& text, const std::string& what) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || text.empty() || value < 0 || value > kMaxFeatureSpecNumber) {
    throw Error("feature spec: " + what + " '" + text + "' is not a whole number in 0.." +
                str(kMaxFeatureSpecNumber));
  }
  return value;
}

}  // namespace

FeatureSpec FeatureSpec::rect() {
  FeatureSpec spec;
  spec.layout = Layout::Rects;
  return spec;
}

std::vector<std::string> FeatureSpec::known_names() { return {"rdsf", "rdsf-rect"}; }

FeatureSpec FeatureSpec::parse(const std::string& text) {
  const std::size_t colon = text.find(':');
  const std::string name = text.substr(0, colon);
  FeatureSpec spec;
  if (name == "rdsf") {
    spec = thesis();
  } else if (name == "rdsf-rect") {
    spec = rect();
  } else {
    throw Error("feature spec '" + name + "' is not known (" + known_text() + ")");
  }
  std::map<std::string, int*> keys = {{"bin", &spec.bin_width_mm}, {"clamp", &spec.max_depth_mm}};
  if (spec.layout == Layout::Cells) {
    keys["cell"] = &spec.cell_px;
  } else {
    keys["min"] = &spec.rect_min_px;
    keys["max"] = &spec.rect_max_px;
    keys["step"] = &spec.rect_step_px;
    keys["stride"] = &spec.rect_stride_px;
  }
  if (colon != std::string::npos) {
    std::string rest = text.substr(colon + 1);
    std::size_t begin = 0;
    while (begin <= rest.size()) {
      const std::size_t comma = std::min(rest.find(',', begin), rest.size());
      const std::string item = rest.substr(begin, comma - begin);
      const std::size_t eq = item.find('=');
      const std::string key = item.substr(0, eq);
      const auto it = keys.find(key);
      if (eq == std::string::npos || it == keys.end()) {
        std::string names;
        for (const auto& k : keys) names += (names.empty() ? "" : ", ") + k.first;
        throw Error("feature spec " + name + ": parameter '" + item + "' is not known (key=value with key " + names +
                    ")");
      }
      *it->second = parse_number(item.substr(eq + 1), name + " " + key);
      begin = comma + 1;
    }
  }
  spec.validate();
  return spec;
}

FeatureSpec FeatureSpec::from_canonical(const std::string& text) {
  static const std::regex cells(
      R"(rdsf/1 window=(\d{1,5})x(\d{1,5}) cell=(\d{1,5}) bins=nodata\+\d{1,5}x(\d{1,5})mm clamp=(\d{1,5})mm )"
      R"(pairs=upper-row-major crop=nearest-masked)");
  static const std::regex rects(
      R"(rdsf-rect/1 window=(\d{1,5})x(\d{1,5}) squares=(\d{1,5})\.\.(\d{1,5})step(\d{1,5}) stride=(\d{1,5}) )"
      R"(order=side-then-row-major bins=nodata\+\d{1,5}x(\d{1,5})mm clamp=(\d{1,5})mm hist=integral-area-normalised )"
      R"(pairs=upper-row-major crop=nearest-masked)");
  // The fields each form's numbers fill, in the order of its groups.
  using F = FeatureSpec;
  static const std::vector<int F::*> cell_fields = {&F::window_width_px, &F::window_height_px, &F::cell_px,
                                                    &F::bin_width_mm, &F::max_depth_mm};
  static const std::vector<int F::*> rect_fields = {&F::window_width_px, &F::window_height_px, &F::rect_min_px,
                                                    &F::rect_max_px, &F::rect_step_px, &F::rect_stride_px,
                                                    &F::bin_width_mm, &F::max_depth_mm};
  std::smatch m;
  FeatureSpec spec;
  const std::vector<int F::*>* fields = nullptr;
  if (std::regex_match(text, m, cells)) {
    fields = &cell_fields;
  } else if (std::regex_match(text, m, rects)) {
    spec.layout = Layout::Rects;
    fields = &rect_fields;
  }
  bool matched = fields != nullptr;
  try {
    for (std::size_t k = 0; matched && k < fields->size(); ++k) {
      spec.*(*fields)[k] = parse_number(m[static_cast<int>(k) + 1].str(), "number");
    }
    if (matched) spec.validate();
  } catch (const Error&) {
    matched = false;
  }
  // The numbers read back must give the very same text (the bin count is derived, for one).
  if (!matched || spec.canonical() != text) {
    throw Error("feature spec '" + text + "' is not one this build knows (" + known_text() + ")");
  }
  return spec;
}

std::string FeatureSpec::option_text() const {
  const FeatureSpec base = layout == Layout::Cells ? thesis() : rect();
  std::string out;
  auto add = [&](const char* key, int value, int default_value) {
    if (value != default_value) out += (out.empty() ? ":" : ",") + std::string(key) + "=" + str(value);
  };
  if (layout == Layout::Cells) {
    add("cell", cell_px, base.cell_px);
  } else {
    add("min", rect_min_px, base.rect_min_px);
    add("max", rect_max_px, base.rect_max_px);
    add("step", rect_step_px, base.rect_step_px);
    add("stride", rect_stride_px, base.rect_stride_px);
  }
  add("bin", bin_width_mm, base.bin_width_mm);
  add("clamp", max_depth_mm, base.max_depth_mm);
  return name() + out;  // the window is fixed by the candidates' crops: not an option
}

int FeatureSpec::region_count() const {
  if (layout == Layout::Cells) return cells_x() * cells_y();
  int n = 0;
  for (int side = rect_min_px; side <= rect_max_px; side += rect_step_px) {
    n += positions(window_width_px, side, rect_stride_px) * positions(window_height_px, side, rect_stride_px);
  }
  return n;
}

std::vector<FeatureRegion> FeatureSpec::regions() const {
  std::vector<FeatureRegion> out;
  if (layout == Layout::Cells) {
    for (int y = 0; y < cells_y(); ++y) {
      for (int x = 0; x < cells_x(); ++x) out.push_back({x * cell_px, y * cell_px, cell_px, cell_px});
    }
    return out;
  }
  for (int side = rect_min_px; side <= rect_max_px; side += rect_step_px) {
    for (int y = 0; y + side <= window_height_px; y += rect_stride_px) {
      for (int x = 0; x + side <= window_width_px; x += rect_stride_px) out.push_back({x, y, side, side});
    }
  }
  return out;
}

FeatureRegion FeatureSpec::region(int r) const {
  if (layout == Layout::Cells) {
    return {(r % cells_x()) * cell_px, (r / cells_x()) * cell_px, cell_px, cell_px};
  }
  for (int side = rect_min_px; side <= rect_max_px; side += rect_step_px) {
    const int across = positions(window_width_px, side, rect_stride_px);
    const int count = across * positions(window_height_px, side, rect_stride_px);
    if (r < count) return {(r % across) * rect_stride_px, (r / across) * rect_stride_px, side, side};
    r -= count;
  }
  throw Error("feature spec: region " + str(r) + " is out of range");
}

void FeatureSpec::pair_at(int index, int& i, int& j) const {
  const int n = region_count();
  i = 0;
  int row_length = n - 1;
  while (index >= row_length) {
    index -= row_length;
    ++i;
    --row_length;
  }
  j = i + 1 + index;
}

std::string FeatureSpec::describe_feature(int index) const {
  int i = 0, j = 0;
  pair_at(index, i, j);
  if (layout == Layout::Cells) return "cells " + str(i) + "-" + str(j);
  auto text = [](const FeatureRegion& r) {
    return str(r.width) + "x" + str(r.height) + "@" + str(r.x) + "," + str(r.y);
  };
  return "rects " + text(region(i)) + "-" + text(region(j));
}

std::string FeatureSpec::canonical() const {
  const std::string bins = " bins=nodata+" + str(bin_count() - 1) + "x" + str(bin_width_mm) + "mm clamp=" +
                           str(max_depth_mm) + "mm";
  const std::string window = " window=" + str(window_width_px) + "x" + str(window_height_px);
  if (layout == Layout::Cells) {
    return "rdsf/1" + window + " cell=" + str(cell_px) + bins + " pairs=upper-row-major crop=nearest-masked";
  }
  return "rdsf-rect/1" + window + " squares=" + str(rect_min_px) + ".." + str(rect_max_px) + "step" +
         str(rect_step_px) + " stride=" + str(rect_stride_px) + " order=side-then-row-major" + bins +
         " hist=integral-area-normalised pairs=upper-row-major crop=nearest-masked";
}

std::string FeatureSpec::hash() const { return to_hex16(fnv1a64(canonical())); }

void FeatureSpec::validate() const {
  for (const int value : {window_width_px, window_height_px, cell_px, rect_min_px, rect_max_px, rect_step_px,
                          rect_stride_px, bin_width_mm, max_depth_mm}) {
    if (value > kMaxFeatureSpecNumber) {
      throw Error("feature spec: number " + str(value) + " is larger than " + str(kMaxFeatureSpecNumber));
    }
  }
  if (window_width_px <= 0 || window_height_px <= 0) throw Error("feature spec: the window must not be empty");
  if (layout == Layout::Cells) {
    if (cell_px <= 0 || window_width_px % cell_px != 0 || window_height_px % cell_px != 0) {
      throw Error("feature spec: cells of " + str(cell_px) + " px must tile the " + str(window_width_px) + "x" +
                  str(window_height_px) + " window");
    }
  } else {
    if (rect_min_px <= 0 || rect_step_px <= 0 || rect_stride_px <= 0 || rect_max_px < rect_min_px) {
      throw Error("feature spec rdsf-rect: sides need 0 < min <= max, step > 0 and stride > 0 (min " +
                  str(rect_min_px) + ", max " + str(rect_max_px) + ", step " + str(rect_step_px) + ", stride " +
                  str(rect_stride_px) + ")");
    }
    if (rect_max_px > window_width_px || rect_max_px > window_height_px) {
      throw Error("feature spec rdsf-rect: squares of " + str(rect_max_px) + " px do not fit the " +
                  str(window_width_px) + "x" + str(window_height_px) + " window");
    }
    if ((rect_max_px - rect_min_px) % rect_step_px != 0) {
      throw Error("feature spec rdsf-rect: max - min must be a multiple of the step");
    }
  }
  // Counted in 64 bits before region_count() is trusted.
  long long regions = 0;
  if (layout == Layout::Cells) {
    regions = static_cast<long long>(window_width_px / cell_px) * (window_height_px / cell_px);
  } else {
    for (int side = rect_min_px; side <= rect_max_px; side += rect_step_px) {
      regions += static_cast<long long>(positions(window_width_px, side, rect_stride_px)) *
                 positions(window_height_px, side, rect_stride_px);
    }
  }
  if (regions < 2) throw Error("feature spec: at least two regions are needed");
  if (regions * (regions - 1) / 2 > kMaxFeatureDimension) {
    throw Error("feature spec: " + std::to_string(regions) + " regions give more than " +
                std::to_string(kMaxFeatureDimension) + " pairs");
  }
  if (bin_width_mm <= 0 || max_depth_mm < bin_width_mm || max_depth_mm % bin_width_mm != 0) {
    throw Error("feature spec: max depth must be a positive multiple of the bin width");
  }
  if (bin_count() > 256) throw Error("feature spec: at most 256 histogram bins (" + str(bin_count()) + " asked)");
}

}  // namespace rdsf
