#pragma once
// Which features a model reads: every feature index its weak classifiers look at (a tree's every node),
// ascending, no repeats. Scoring needs only these (features/feature_subset.hpp); a 100-round model of
// stumps or look-up tables reads at most 100, of depth-d trees at most 100 (2^d - 1).
#include <functional>
#include <vector>

#include "rdsf/classifier/boosted_model.hpp"

namespace rdsf {

std::vector<int> features_read(const std::vector<WeakClassifier>& weak);
inline std::vector<int> features_read(const BoostedModel& model) { return features_read(model.weak_classifiers()); }

/// Replaces every feature index the weak classifiers read (a tree's root and nodes) by `map(index)`.
void renumber_features(std::vector<WeakClassifier>& weak, const std::function<int(int)>& map);

}  // namespace rdsf
