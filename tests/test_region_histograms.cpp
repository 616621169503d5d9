// RegionHistogramBuilder's root histograms (dense and sparse) against the definition written out pixel by
// pixel, bit for bit: the 8 x 8 blocks' register path (occupied bins only, straight to the slot, or into
// the integral histogram of the rectangles), the general vector path (16-pixel cells) and the scalar one,
// on crops built to reach every branch: uniform blocks, blocks of zeros, zeros and one bin, depths on and
// around every bin edge, spans with empty bins between occupied ones, 65535, noise. pair_value_short (no
// branches on the data) against pair_value on every pair it takes, histograms reused from crop to crop
// and from spec to spec (stale entries past nz_count).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <algorithm>
#include <random>

#include "rdsf/features/region_histograms.hpp"

using namespace rdsf;

namespace {

cv::Mat1w mixed_crop(const FeatureSpec& spec, unsigned seed) {
  std::mt19937 random(seed);
  cv::Mat1w crop(spec.window_height_px, spec.window_width_px, std::uint16_t{0});
  const int bins = spec.bin_count();
  auto near_edge = [&] {  // a depth within 2 mm of a bin edge
    const int edge = static_cast<int>(random() % static_cast<unsigned>(bins)) * spec.bin_width_mm;
    return std::clamp(edge + static_cast<int>(random() % 5) - 2, 0, 65535);
  };
  for (int by = 0; by < crop.rows; by += 8) {
    for (int bx = 0; bx < crop.cols; bx += 8) {
      const int kind = static_cast<int>(random() % 8);
      const int base = 1 + static_cast<int>(random() % 9000);
      for (int y = by; y < by + 8; ++y) {
        for (int x = bx; x < bx + 8; ++x) {
          int d = 0;
          switch (kind) {
            case 0: d = base; break;                                              // one depth
            case 1: d = 0; break;                                                 // no readings
            case 2: d = random() % 3 == 0 ? 0 : base; break;                      // zeros and one bin
            case 3: d = near_edge(); break;                                       // on and around edges
            case 4: d = random() % 2 ? 1200 : 6600 + static_cast<int>(random() % 3); break;  // empty bins between
            case 5: d = static_cast<int>(random() % 65536); break;                // anything
            case 6: d = random() % 4 == 0 ? 65535 : (random() % 4 == 0 ? 0 : base + static_cast<int>(random() % 700)); break;
            default: d = base + (x - bx) * 97 + (y - by) * 13; break;             // a ramp over several bins
          }
          crop(y, x) = static_cast<std::uint16_t>(d);
        }
      }
    }
  }
  return crop;
}

std::uint32_t bits(float f) {
  std::uint32_t b = 0;
  std::memcpy(&b, &f, sizeof b);
  return b;
}

// The definition: per region, count its pixels per bin; root = sqrt(float(c) / float(A)); the sparse list
// is the non-zero bins ascending.
void expect_definition(const FeatureSpec& spec, const cv::Mat1w& crop, const std::vector<int>& regions,
                       const RootHistograms& h) {
  const int bins = spec.bin_count();
  const std::vector<FeatureRegion> all = spec.regions();
  ASSERT_EQ(h.bins, bins);
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const FeatureRegion& r = all[static_cast<std::size_t>(regions[k])];
    std::vector<int> counts(static_cast<std::size_t>(bins), 0);
    for (int y = r.y; y < r.y + r.height; ++y) {
      for (int x = r.x; x < r.x + r.width; ++x) {
        const int d = crop(y, x);
        ++counts[static_cast<std::size_t>(d == 0 ? 0 : std::min(1 + d / spec.bin_width_mm, bins - 1))];
      }
    }
    int n = 0;
    for (int b = 0; b < bins; ++b) {
      const int c = counts[static_cast<std::size_t>(b)];
      const float root = std::sqrt(static_cast<float>(c) / static_cast<float>(r.area()));
      const std::size_t at = k * static_cast<std::size_t>(bins);
      ASSERT_EQ(bits(h.dense[at + static_cast<std::size_t>(b)]), bits(root)) << spec.canonical() << " slot " << k << " bin " << b;
      if (c == 0) continue;
      ASSERT_LT(n, h.nz_count[k]) << spec.canonical() << " slot " << k;
      ASSERT_EQ(h.nz_bin[at + static_cast<std::size_t>(n)], b) << spec.canonical() << " slot " << k;
      ASSERT_EQ(bits(h.nz_root[at + static_cast<std::size_t>(n)]), bits(root)) << spec.canonical() << " slot " << k;
      ++n;
    }
    ASSERT_EQ(n, h.nz_count[k]) << spec.canonical() << " slot " << k;
  }
}

std::vector<FeatureSpec> specs() {
  std::vector<FeatureSpec> out = {FeatureSpec{}, FeatureSpec::rect(),
                                  FeatureSpec::parse("rdsf-rect:min=4,max=20,step=8,stride=12")};
  FeatureSpec fine;  // 76 bins of 100 mm
  fine.bin_width_mm = 100;
  FeatureSpec coarse;  // 8 bins of 1 m
  coarse.bin_width_mm = 1000;
  coarse.max_depth_mm = 7000;
  FeatureSpec cells16;  // the general vector path
  cells16.cell_px = 16;
  FeatureSpec cells4;  // the scalar path
  cells4.cell_px = 4;
  for (const FeatureSpec& s : {fine, coarse, cells16, cells4}) out.push_back(s);
  return out;
}

TEST(RegionHistograms, EveryRegionEqualsTheDefinitionBitForBit) {
  for (const FeatureSpec& spec : specs()) {
    const RegionHistogramBuilder builder(spec);
    for (unsigned seed = 1; seed <= 6; ++seed) {
      const cv::Mat1w crop = mixed_crop(spec, seed);
      RootHistograms h;
      builder.compute_all(crop, h);
      std::vector<int> all(static_cast<std::size_t>(spec.region_count()));
      for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
      expect_definition(spec, crop, all, h);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
}

TEST(RegionHistograms, SomeRegionsInAnyOrderEqualTheDefinition) {
  for (const FeatureSpec& spec : specs()) {
    const RegionHistogramBuilder builder(spec);
    std::mt19937 random(5);
    std::vector<int> some;
    for (int k = 0; k < 40; ++k) some.push_back(static_cast<int>(random() % static_cast<unsigned>(spec.region_count())));
    const cv::Mat1w crop = mixed_crop(spec, 9);
    RootHistograms h;
    builder.compute(crop, some, h);
    expect_definition(spec, crop, some, h);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

TEST(RegionHistograms, ShortPairValueEqualsPairValue) {
  RootHistograms h;  // reused: entries past each slot's nz_count hold earlier crops' and specs' values
  std::size_t checked = 0;
  for (int round = 0; round < 2; ++round) {
    for (const FeatureSpec& spec : specs()) {
      const RegionHistogramBuilder builder(spec);
      for (unsigned seed = 11; seed <= 13; ++seed) {
        builder.compute_all(mixed_crop(spec, seed + static_cast<unsigned>(round)), h);
        ASSERT_GE(h.bins, 4);
        const int slots = std::min(spec.region_count(), 160);
        for (int i = 0; i < slots; ++i) {
          for (int j = 0; j < slots; ++j) {
            if (h.nz_count[static_cast<std::size_t>(j)] > 4) continue;
            ASSERT_EQ(bits(pair_value_short(h, i, j)), bits(pair_value(h, i, j))) << spec.canonical() << " " << i << ", " << j;
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 100000u);
}

}  // namespace
