#pragma once
// One weak classifier of a boosted model: a function of a single feature value.
//   - kind Lut (native Real AdaBoost, domain partitioning): responses[bin_of(value)], one real response per
//     bin of the model's BinScheme;
//   - kind Stump (the OpenCV backend's depth-1 trees): value <= threshold ? left : right, exactly as
//     cv::ml::DTrees evaluates an ordered split (OpenCV's "inversed" splits are stored swapped).
#include <vector>

#include "classifier/bin_scheme.hpp"

namespace rdsf {

struct WeakClassifier {
  enum class Kind { Lut, Stump };
  Kind kind = Kind::Lut;
  int feature = 0;                 ///< index into the 8128-value feature vector
  std::vector<double> responses;   ///< Lut: one per bin
  double threshold = 0.0;          ///< Stump
  double left = 0.0, right = 0.0;  ///< Stump: responses at or below / above the threshold

  double respond(float value, const BinScheme& bins) const {
    if (kind == Kind::Lut) return responses[static_cast<std::size_t>(bins.bin_of(value))];
    return value <= threshold ? left : right;
  }
  bool operator==(const WeakClassifier& o) const {
    return kind == o.kind && feature == o.feature && responses == o.responses && threshold == o.threshold &&
           left == o.left && right == o.right;
  }
};

}  // namespace rdsf
