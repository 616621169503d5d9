#pragma once
// BinScheme::bin_of for a whole row of values at once, four at a time in SSE2 lanes (scalar without it).
// Per value v: scaled = (v - min_value) * float(count) / (max_value - min_value), the same three IEEE float
// operations in the same order as bin_of (each correctly rounded, so a lane gives the scalar's bits), then
// bin = 0 when !(scaled > 0) (NaN included), else trunc(min(scaled, count - 1)).
// Invariant: bin_row(v) == bin_of(v) for every v where bin_of is defined, i.e. every float whose scaled
// value is below 2^31 (above that bin_of's float-to-int conversion overflows; bin_row gives count - 1).
// Tested on every float in [0, 1], around each bin edge, NaN, infinities, negatives and values above the
// range (tests/test_bin_row.cpp).
#include <cstdint>

#include "rdsf/classifier/bin_scheme.hpp"

namespace rdsf {

/// The bin of one value as bin_row computes it (the scalar tail of bin_row; == bin_of where defined).
inline int bin_clamped(const BinScheme& bins, float value) {
  const float scaled = (value - bins.min_value) * static_cast<float>(bins.count) / (bins.max_value - bins.min_value);
  if (!(scaled > 0.0f)) return 0;
  const float top = static_cast<float>(bins.count - 1);
  return static_cast<int>(scaled < top ? scaled : top);
}

/// out[k] = bin of values[k] for k < n (see the header comment).
void bin_row(const BinScheme& bins, const float* values, int n, std::uint8_t* out);

}  // namespace rdsf
