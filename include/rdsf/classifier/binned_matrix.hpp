#pragma once
// Feature values quantised to 8-bit bin indices and stored feature-major: the bins of one feature for all
// samples are contiguous, which is what the boosting rounds read (one feature at a time, every sample).
// At hugeTree size (28,082 samples x 8128 features) this is 228 MB instead of 913 MB of floats.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "rdsf/classifier/bin_scheme.hpp"

namespace rdsf {

class BinnedMatrix {
 public:
  BinnedMatrix() = default;
  /// Quantises `rows` (one sample per row, CV_32F) with `scheme`, in parallel over row blocks. When
  /// `row_order` is given, sample s of the result is rows.row(row_order[s]). threads <= 0: all cores.
  BinnedMatrix(const cv::Mat1f& rows, const BinScheme& scheme, const std::vector<std::size_t>& row_order = {},
               int threads = 0);

  std::size_t samples() const { return samples_; }
  std::size_t features() const { return features_; }
  const BinScheme& scheme() const { return scheme_; }
  /// The bins of feature `f` for every sample (samples() values).
  const std::uint8_t* feature(std::size_t f) const { return bins_.data() + f * samples_; }
  std::uint8_t at(std::size_t f, std::size_t sample) const { return bins_[f * samples_ + sample]; }

 private:
  std::size_t samples_ = 0, features_ = 0;
  BinScheme scheme_;
  std::vector<std::uint8_t> bins_;
};

}  // namespace rdsf
