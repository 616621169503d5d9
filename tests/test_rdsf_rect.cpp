// The rectangle feature spec "rdsf-rect" (after Ikemura and Fujiyoshi), spec texts and names, and the
// features computed only for a subset: brute force against the integral histograms, subset == full.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "rdsf/core/error.hpp"
#include "support/test_support.hpp"
#include "rdsf/features/feature_subset.hpp"
#include "rdsf/features/rdsf_extractor.hpp"

using namespace rdsf;

namespace {

// A crop with people-like structure: a masked background (0), a body at one depth with a ragged edge,
// a few missing readings and a far wall, so that regions hold one, two or several bins.
cv::Mat1w hand_built_crop(unsigned seed) {
  std::mt19937 random(seed);
  cv::Mat1w crop(128, 64, std::uint16_t{0});
  for (int y = 0; y < 128; ++y) {
    for (int x = 0; x < 64; ++x) {
      const int half_width = 10 + (y > 30 ? 8 : 0) + static_cast<int>(random() % 3);
      if (std::abs(x - 32) < half_width) crop(y, x) = static_cast<std::uint16_t>(2400 + (x * 7 + y) % 500);
      if (y > 100 && x < 12) crop(y, x) = 6900;                        // far wall
      if (random() % 17 == 0) crop(y, x) = 0;                           // missing reading
      if (random() % 53 == 0) crop(y, x) = static_cast<std::uint16_t>(random() % 12000);  // anything
    }
  }
  return crop;
}

// The definition, written out: count the pixels of each region per bin, p_b = c_b / A, coefficient =
// sequential sum over all bins of sqrt(p_b) sqrt(q_b), clamped to 1.
std::vector<float> brute_force(const FeatureSpec& spec, const cv::Mat1w& crop) {
  const int bins = spec.bin_count();
  std::vector<std::vector<float>> roots;
  for (const FeatureRegion& r : spec.regions()) {
    std::vector<int> counts(static_cast<std::size_t>(bins), 0);
    for (int y = r.y; y < r.y + r.height; ++y) {
      for (int x = r.x; x < r.x + r.width; ++x) {
        const int d = crop(y, x);
        const int bin = d == 0 ? 0 : std::min(1 + d / spec.bin_width_mm, bins - 1);
        ++counts[static_cast<std::size_t>(bin)];
      }
    }
    std::vector<float> root(static_cast<std::size_t>(bins));
    for (int b = 0; b < bins; ++b) {
      root[static_cast<std::size_t>(b)] =
          std::sqrt(static_cast<float>(counts[static_cast<std::size_t>(b)]) / static_cast<float>(r.area()));
    }
    roots.push_back(root);
  }
  std::vector<float> out;
  for (std::size_t i = 0; i < roots.size(); ++i) {
    for (std::size_t j = i + 1; j < roots.size(); ++j) {
      float sum = 0.0f;
      for (int b = 0; b < bins; ++b) sum += roots[i][static_cast<std::size_t>(b)] * roots[j][static_cast<std::size_t>(b)];
      out.push_back(std::min(sum, 1.0f));
    }
  }
  return out;
}

using test::error_message;
const auto& error_of = error_message;

}  // namespace

TEST(RectSpec, HasThePapersRectanglesAndAStableText) {
  const FeatureSpec spec = FeatureSpec::rect();
  EXPECT_EQ(spec.name(), "rdsf-rect");
  EXPECT_EQ(spec.region_count(), 128 + 105 + 84 + 65 + 48 + 33 + 20 + 9);  // sides 8..64 at an 8 px stride
  EXPECT_EQ(spec.dimension(), 492 * 491 / 2);
  EXPECT_EQ(spec.bin_count(), 26);
  // Sample sets and model files carry these: change them only on purpose.
  EXPECT_EQ(spec.canonical(),
            "rdsf-rect/1 window=64x128 squares=8..64step8 stride=8 order=side-then-row-major "
            "bins=nodata+25x300mm clamp=7500mm hist=integral-area-normalised pairs=upper-row-major "
            "crop=nearest-masked");
  EXPECT_EQ(spec.hash(), "b23cd6a8512cbee0");
  EXPECT_NE(spec.hash(), FeatureSpec{}.hash());
  EXPECT_EQ(FeatureSpec{}.name(), "rdsf");
}

TEST(RectSpec, RegionsAreOrderedBySideThenRowMajor) {
  const FeatureSpec spec = FeatureSpec::rect();
  const std::vector<FeatureRegion> regions = spec.regions();
  ASSERT_EQ(static_cast<int>(regions.size()), spec.region_count());
  EXPECT_EQ(regions[0].x, 0);
  EXPECT_EQ(regions[1].x, 8);
  EXPECT_EQ(regions[8].y, 8);
  EXPECT_EQ(regions[128].width, 16);  // the first 16x16 square
  EXPECT_EQ(regions[128].x, 0);
  EXPECT_EQ(regions[129].x, 8);
  EXPECT_EQ(regions.back().width, 64);
  EXPECT_EQ(regions.back().y, 64);
  for (int r = 0; r < spec.region_count(); r += 7) {
    EXPECT_EQ(spec.region(r).x, regions[static_cast<std::size_t>(r)].x);
    EXPECT_EQ(spec.region(r).y, regions[static_cast<std::size_t>(r)].y);
    EXPECT_EQ(spec.region(r).width, regions[static_cast<std::size_t>(r)].width);
  }
  EXPECT_EQ(spec.describe_feature(spec.pair_index(0, 128)), "rects 8x8@0,0-16x16@0,0");
  EXPECT_EQ(FeatureSpec{}.describe_feature(127), "cells 1-2");
}

TEST(RectSpec, NamesAndParametersParse) {
  EXPECT_EQ(FeatureSpec::parse("rdsf"), FeatureSpec{});
  EXPECT_EQ(FeatureSpec::parse("rdsf-rect"), FeatureSpec::rect());
  const FeatureSpec small = FeatureSpec::parse("rdsf-rect:max=32,stride=16");
  EXPECT_EQ(small.rect_max_px, 32);
  EXPECT_EQ(small.rect_stride_px, 16);
  EXPECT_EQ(small.option_text(), "rdsf-rect:max=32,stride=16");
  EXPECT_EQ(FeatureSpec::parse(small.option_text()), small);
  EXPECT_EQ(FeatureSpec::parse("rdsf:cell=16").cell_px, 16);
  EXPECT_EQ(FeatureSpec::rect().option_text(), "rdsf-rect");
  EXPECT_NE(error_of([] { FeatureSpec::parse("hog"); }).find("'hog' is not known"), std::string::npos);
  EXPECT_NE(error_of([] { FeatureSpec::parse("rdsf-rect:size=3"); }).find("'size=3' is not known"), std::string::npos);
  EXPECT_NE(error_of([] { FeatureSpec::parse("rdsf:min=8"); }).find("not known"), std::string::npos);
  EXPECT_NE(error_of([] { FeatureSpec::parse("rdsf-rect:max=x"); }).find("not a whole number"), std::string::npos);
  EXPECT_NE(error_of([] { FeatureSpec::parse("rdsf-rect:max=128"); }).find("do not fit"), std::string::npos);
  EXPECT_NE(error_of([] { FeatureSpec::parse("rdsf-rect:min=1,step=1,stride=1"); }).find("pairs"), std::string::npos);
}

TEST(RectSpec, CanonicalTextsReadBackAndUnknownOnesAreRefused) {
  for (const FeatureSpec& spec : {FeatureSpec{}, FeatureSpec::rect(), FeatureSpec::parse("rdsf:cell=16,bin=250"),
                                  FeatureSpec::parse("rdsf-rect:min=16,max=48,step=16,stride=8")}) {
    const FeatureSpec again = FeatureSpec::from_canonical(spec.canonical());
    EXPECT_EQ(again.canonical(), spec.canonical());
    EXPECT_EQ(again.hash(), spec.hash());
  }
  std::string text = FeatureSpec::rect().canonical();
  text.replace(text.find("nodata+25"), 9, "nodata+24");  // bin count that does not follow from the numbers
  const std::string message = error_of([&] { FeatureSpec::from_canonical(text); });
  EXPECT_NE(message.find("is not one this build knows"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  EXPECT_FALSE(error_of([] { FeatureSpec::from_canonical("hog/1 window=64x128"); }).empty());
  EXPECT_FALSE(error_of([] { FeatureSpec::from_canonical("rdsf/1 window=64x128 cell=7 bins=nodata+25x300mm "
                                                         "clamp=7500mm pairs=upper-row-major crop=nearest-masked"); })
                   .empty());
}

TEST(RectSpec, IntegralHistogramsEqualBruteForceBitForBit) {
  for (const FeatureSpec& spec : {FeatureSpec::rect(), FeatureSpec::parse("rdsf-rect:min=4,max=20,step=8,stride=12"),
                                  FeatureSpec{}}) {
    const RdsfExtractor extractor(spec);
    for (unsigned seed : {1u, 2u}) {
      const cv::Mat1w crop = hand_built_crop(seed);
      const std::vector<float> fast = extractor.compute(crop);
      const std::vector<float> slow = brute_force(spec, crop);
      ASSERT_EQ(fast.size(), slow.size()) << spec.canonical();
      std::size_t differ = 0;
      for (std::size_t k = 0; k < fast.size(); ++k) differ += fast[k] != slow[k] ? 1 : 0;
      EXPECT_EQ(differ, 0u) << spec.canonical();
    }
  }
}

TEST(RectSpec, LargerSquaresAverageTheirCells) {
  // A crop half at 1 m (left) and half at 4 m (right): the 64x64 squares see half of each, the 8x8 squares one.
  cv::Mat1w crop(128, 64, std::uint16_t{1000});
  crop(cv::Rect(32, 0, 32, 128)).setTo(4000);
  const FeatureSpec spec = FeatureSpec::rect();
  const RdsfExtractor extractor(spec);
  const std::vector<float> f = extractor.compute(crop);
  const int big = spec.region_count() - 1;  // 64x64 at (0, 64)
  EXPECT_FLOAT_EQ(f[static_cast<std::size_t>(spec.pair_index(0, big))], std::sqrt(0.5f));  // 8x8 at (0,0): all 1 m
  EXPECT_FLOAT_EQ(f[static_cast<std::size_t>(spec.pair_index(0, 7))], 0.0f);               // 8x8 at (56,0): all 4 m
  EXPECT_FLOAT_EQ(f[static_cast<std::size_t>(spec.pair_index(big - 1, big))], 1.0f);
  const cv::Mat1f h = extractor.cell_histograms(crop);
  EXPECT_FLOAT_EQ(h(big, extractor.bin_of(1000)), 0.5f);
  EXPECT_FLOAT_EQ(h(big, extractor.bin_of(4000)), 0.5f);
}

TEST(FeatureSubset, ValuesEqualTheFullVectorBitForBit) {
  for (const FeatureSpec& spec : {FeatureSpec{}, FeatureSpec::rect()}) {
    const RdsfExtractor extractor(spec);
    std::mt19937 random(3);
    std::vector<int> chosen;
    for (int k = 0; k < 150; ++k) chosen.push_back(static_cast<int>(random() % static_cast<unsigned>(spec.dimension())));
    chosen.push_back(0);
    chosen.push_back(spec.dimension() - 1);
    chosen.push_back(chosen[5]);  // a repeat
    const FeatureSubset subset(spec, chosen);
    EXPECT_EQ(subset.size(), static_cast<int>(chosen.size()) - 1);
    EXPECT_LE(subset.region_count(), 2 * subset.size());
    for (unsigned seed : {4u, 5u, 6u}) {
      const cv::Mat1w crop = hand_built_crop(seed);
      const std::vector<float> full = extractor.compute(crop);
      std::vector<float> some(static_cast<std::size_t>(subset.size()));
      subset.compute(crop, some.data());
      for (int k = 0; k < subset.size(); ++k) {
        const int f = subset.features()[static_cast<std::size_t>(k)];
        EXPECT_EQ(some[static_cast<std::size_t>(k)], full[static_cast<std::size_t>(f)]) << spec.name() << " " << f;
        EXPECT_EQ(subset.position(f), k);
      }
    }
  }
  EXPECT_EQ(FeatureSubset(FeatureSpec{}, {5}).position(6), -1);
  EXPECT_THROW(FeatureSubset(FeatureSpec{}, {8128}), Error);
  EXPECT_THROW(FeatureSubset(FeatureSpec{}, {-1}), Error);
}
