#pragma once
// The training rows of the hugeTree-size comparison: real RDSF vectors of generated 64x128 masked depth
// crops, made the way bench/bench_train.cpp makes them (person-like silhouettes against furniture-like
// clutter, with noise, missing readings and occlusion), so that both reports train on the same kind of data.
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/classifier/binned_matrix.hpp"
#include "rdsf/features/feature_spec.hpp"

namespace rdsf::perf {

struct TrainingRows {
  cv::Mat1f rows;           ///< one RDSF vector per row
  std::vector<int> labels;  ///< 1 person, 0 not (shuffled)
};

/// `positives` + `negatives` rows, deterministic for a seed, computed on all cores: every feature of `spec`,
/// or only the features `columns` (ascending) when given.
TrainingRows make_training_rows(int positives, int negatives, std::uint64_t seed, const FeatureSpec& spec = {},
                                const std::vector<int>& columns = {});

/// `rows` binned (64 bins) positives first, RealAdaBoost's faster sample order, with their labels in that
/// order and the wall time the binning took.
struct BinnedRows {
  BinnedMatrix matrix;
  std::vector<int> labels;
  double seconds = 0;
};
BinnedRows bin_positives_first(const TrainingRows& rows, int threads);

}  // namespace rdsf::perf
