#pragma once
// Which features a model reads: every feature index its weak classifiers look at, ascending, no repeats.
// Scoring needs only these (features/feature_subset.hpp); a 100-round model of stumps or look-up tables
// reads at most 100. When a weak classifier reads several features (tree nodes), list them all here.
#include <vector>

#include "classifier/boosted_model.hpp"

namespace rdsf {

std::vector<int> features_read(const std::vector<WeakClassifier>& weak);
inline std::vector<int> features_read(const BoostedModel& model) { return features_read(model.weak_classifiers()); }

}  // namespace rdsf
