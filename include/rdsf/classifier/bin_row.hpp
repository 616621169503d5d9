#pragma once
// BinScheme::bin_of for a whole row of values at once, four at a time in SSE2 lanes (scalar without it).
// Per value v the three IEEE float operations of BinScheme::bin_of in the same order (each correctly
// rounded, so a lane gives the scalar's bits), then its clamp and truncation: bin_row(v) == bin_of(v) for
// every float.
// Tested on every float in [0, 1], around each bin edge, NaN, infinities, negatives and values above the
// range (tests/test_bin_row.cpp).
#include <cstdint>

#include "rdsf/classifier/bin_scheme.hpp"

namespace rdsf {

/// out[k] = bin of values[k] for k < n (see the header comment).
void bin_row(const BinScheme& bins, const float* values, int n, std::uint8_t* out);

}  // namespace rdsf
