// bin_row (four values at a time) gives BinScheme::bin_of's bin for every float in [0, 1], around every
// bin edge, for NaN, negatives and values above the range, in the shipped model's scheme, the default
// one and an offset range.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "rdsf/classifier/bin_row.hpp"

using namespace rdsf;

namespace {

float float_of(std::uint32_t bits) {
  float f = 0.0f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// bin_row over values, checked against bin_of one by one (in chunks, odd sizes for the scalar tail).
void expect_same(const BinScheme& scheme, const std::vector<float>& values) {
  std::vector<std::uint8_t> bins(values.size());
  bin_row(scheme, values.data(), static_cast<int>(values.size()), bins.data());
  for (std::size_t k = 0; k < values.size(); ++k) {
    ASSERT_EQ(bins[k], scheme.bin_of(values[k])) << "value " << values[k] << " at " << k;
  }
}

void every_float_in_unit_range(const BinScheme& scheme) {
  const std::uint32_t one = 0x3f800000u;  // the bits of 1.0f; floats in [0, 1] are bits 0..one
  constexpr std::uint32_t kChunk = 1u << 20;
  std::vector<float> values(kChunk + 3);
  std::vector<std::uint8_t> bins(values.size());
  for (std::uint32_t start = 0; start <= one; start += kChunk) {
    const std::uint32_t n = std::min<std::uint32_t>(static_cast<std::uint32_t>(values.size()), one - start + 1);
    for (std::uint32_t k = 0; k < n; ++k) values[k] = float_of(start + k);
    bin_row(scheme, values.data(), static_cast<int>(n), bins.data());
    for (std::uint32_t k = 0; k < n; ++k) {
      if (bins[k] != scheme.bin_of(values[k])) FAIL() << "value " << values[k] << " (bits " << start + k << ")";
    }
  }
}

std::vector<float> awkward_values(const BinScheme& scheme) {
  std::vector<float> out = {std::numeric_limits<float>::quiet_NaN(), -std::numeric_limits<float>::quiet_NaN(),
                            -std::numeric_limits<float>::infinity(), -1e30f, -1.0f, -0.0f, 0.0f,
                            std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::min(),
                            1.0f, 1.5f, 2.0f, 100.0f, 1e6f, 1e30f, std::numeric_limits<float>::infinity()};
  // every bin edge and the 64 floats either side of it
  for (int b = 0; b <= scheme.count; ++b) {
    float edge = scheme.lower_edge(b);
    for (int k = 0; k < 64; ++k) edge = std::nextafter(edge, -1e30f);
    for (int k = 0; k < 129; ++k, edge = std::nextafter(edge, 1e30f)) out.push_back(edge);
  }
  return out;
}

TEST(BinRow, ShippedSchemeEveryFloatInZeroOne) { every_float_in_unit_range(BinScheme{32, 0.0f, 1.0f}); }
TEST(BinRow, DefaultSchemeEveryFloatInZeroOne) { every_float_in_unit_range(BinScheme{}); }

TEST(BinRow, EdgesNanNegativesAndAboveTheRange) {
  for (const BinScheme& scheme : {BinScheme{32, 0.0f, 1.0f}, BinScheme{64, 0.0f, 1.0f}, BinScheme{256, 0.0f, 1.0f},
                                  BinScheme{2, 0.0f, 1.0f}, BinScheme{50, 0.25f, 0.75f}, BinScheme{7, -3.0f, 11.0f}}) {
    std::vector<float> values = awkward_values(scheme);
    expect_same(scheme, values);
    for (std::size_t skip = 1; skip < 20; ++skip) {  // every alignment of the 16-wide lanes and the tail
      expect_same(scheme, std::vector<float>(values.begin() + static_cast<long>(skip), values.end()));
    }
  }
}

TEST(BinRow, OffsetRangeEveryFloatInIt) {
  const BinScheme scheme{50, 0.25f, 0.75f};
  std::vector<float> values;
  for (float v = 0.2f; v <= 0.8f; v = std::nextafter(v, 1.0f)) values.push_back(v);
  expect_same(scheme, values);
}

}  // namespace
