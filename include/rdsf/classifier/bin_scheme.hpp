#pragma once
// How a feature value becomes a bin index for the look-up-table weak classifiers: `count` equal bins over
// [min_value, max_value]. RDSF values are Bhattacharyya coefficients in [0, 1], so the default is 64 bins
// of width 1/64 over [0, 1]. Values below the range fall into bin 0, values at or above the top (and NaN)
// into the nearest end bin. The scheme is stored in every model file.
#include <cmath>
#include <cstdint>

namespace rdsf {

struct BinScheme {
  int count = 64;          ///< number of bins, 2..256 (bin indices are stored as 8-bit values)
  float min_value = 0.0f;  ///< lower edge of bin 0
  float max_value = 1.0f;  ///< upper edge of the last bin

  /// Bin index of `value` in [0, count): scaled = (value - min_value) * count / (max_value - min_value), 0
  /// when !(scaled > 0) (NaN too), else trunc(min(scaled, count - 1)), clamped before the conversion so a
  /// huge value or +infinity is the last bin (bin_row.hpp computes the same in SSE2 lanes).
  int bin_of(float value) const {
    const float scaled = (value - min_value) * static_cast<float>(count) / (max_value - min_value);
    if (!(scaled > 0.0f)) return 0;  // also NaN
    const float top = static_cast<float>(count - 1);
    return static_cast<int>(scaled < top ? scaled : top);
  }
  /// Lower edge of bin `bin`.
  float lower_edge(int bin) const {
    return min_value + (max_value - min_value) * static_cast<float>(bin) / static_cast<float>(count);
  }
  /// Throws Error when count is out of 2..256 or the range is empty.
  void validate() const;
  bool operator==(const BinScheme& o) const {
    return count == o.count && min_value == o.min_value && max_value == o.max_value;
  }
};

}  // namespace rdsf
