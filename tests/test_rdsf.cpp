#include <gtest/gtest.h>

#include <random>

#include "rdsf/core/error.hpp"
#include "rdsf/features/rdsf_extractor.hpp"

using namespace rdsf;

namespace {

cv::Mat1w crop(std::uint16_t fill = 0) { return cv::Mat1w(128, 64, fill); }
cv::Mat1w cell_view(cv::Mat1w& image, int cell) { return image(cv::Rect((cell % 8) * 8, (cell / 8) * 8, 8, 8)); }

}  // namespace

TEST(FeatureSpec, DefaultIsTheThesisRdsf) {
  const FeatureSpec spec;
  EXPECT_EQ(spec.cell_count(), 128);
  EXPECT_EQ(spec.bin_count(), 26);  // no reading + 25 bins of 0.3 m up to 7.5 m
  EXPECT_EQ(spec.dimension(), 8128);
  EXPECT_EQ(spec.hash().size(), 16u);
  EXPECT_EQ(spec.hash(), FeatureSpec{}.hash());
  FeatureSpec other;
  other.bin_width_mm = 250;
  EXPECT_NE(other.hash(), spec.hash());
}

TEST(FeatureSpec, HashIsStableAcrossBuilds) {
  // Sample sets and model files carry this value: changing it orphans them. Change it only on purpose.
  EXPECT_EQ(FeatureSpec{}.canonical(),
            "rdsf/1 window=64x128 cell=8 bins=nodata+25x300mm clamp=7500mm pairs=upper-row-major "
            "crop=nearest-masked");
  EXPECT_EQ(FeatureSpec{}.hash(), "48d0ea6f3a48b97c");
}

TEST(FeatureSpec, PairOrderIsUpperTriangleRowMajor) {
  const FeatureSpec spec;
  EXPECT_EQ(spec.pair_index(0, 1), 0);
  EXPECT_EQ(spec.pair_index(0, 127), 126);
  EXPECT_EQ(spec.pair_index(1, 2), 127);
  EXPECT_EQ(spec.pair_index(126, 127), 8127);
  for (int index : {0, 1, 126, 127, 4000, 8127}) {
    int i = 0, j = 0;
    spec.pair_at(index, i, j);
    EXPECT_LT(i, j);
    EXPECT_EQ(spec.pair_index(i, j), index);
  }
}

TEST(FeatureSpec, InvalidSpecsAreRefused) {
  FeatureSpec spec;
  spec.cell_px = 7;
  EXPECT_THROW(spec.validate(), Error);
  EXPECT_THROW(RdsfExtractor{spec}, Error);
}

TEST(Rdsf, BinsAreNoReadingThenThirtyCentimetres) {
  const RdsfExtractor rdsf;
  EXPECT_EQ(rdsf.bin_of(0), 0);
  EXPECT_EQ(rdsf.bin_of(1), 1);
  EXPECT_EQ(rdsf.bin_of(299), 1);
  EXPECT_EQ(rdsf.bin_of(300), 2);
  EXPECT_EQ(rdsf.bin_of(7499), 25);
  EXPECT_EQ(rdsf.bin_of(7500), 25);  // beyond the last bin: clamped
  EXPECT_EQ(rdsf.bin_of(12000), 25);
}

TEST(Rdsf, LengthAndRange) {
  const RdsfExtractor rdsf;
  std::mt19937 random(7);
  cv::Mat1w image = crop();
  for (auto& d : image) d = static_cast<std::uint16_t>(random() % 9000);
  const std::vector<float> f = rdsf.compute(image);
  ASSERT_EQ(f.size(), 8128u);
  for (float v : f) {
    EXPECT_GE(v, 0.0f);
    EXPECT_LE(v, 1.0f);
  }
}

TEST(Rdsf, IdenticalCellsGiveOne) {
  const RdsfExtractor rdsf;
  for (float v : rdsf.compute(crop(2000))) EXPECT_FLOAT_EQ(v, 1.0f);
  for (float v : rdsf.compute(crop(0))) EXPECT_FLOAT_EQ(v, 1.0f);  // all "no reading"
}

TEST(Rdsf, DisjointHistogramsGiveZero) {
  const RdsfExtractor rdsf;
  cv::Mat1w image = crop(1000);
  cell_view(image, 5).setTo(4000);
  const std::vector<float> f = rdsf.compute(image);
  const FeatureSpec& spec = rdsf.spec();
  EXPECT_FLOAT_EQ(f[static_cast<std::size_t>(spec.pair_index(0, 5))], 0.0f);
  EXPECT_FLOAT_EQ(f[static_cast<std::size_t>(spec.pair_index(5, 127))], 0.0f);
  EXPECT_FLOAT_EQ(f[static_cast<std::size_t>(spec.pair_index(0, 1))], 1.0f);
}

TEST(Rdsf, WorkedExampleAndFixedOrder) {
  const RdsfExtractor rdsf;
  cv::Mat1w image = crop(0);
  cell_view(image, 0).setTo(1000);  // cell 0: all in bin 4
  cv::Mat1w cell1 = cell_view(image, 1);
  cell1(cv::Rect(0, 0, 8, 4)).setTo(1000);  // cell 1: half bin 4, half no reading
  cv::Mat1w cell2 = cell_view(image, 2);
  cell2(cv::Rect(0, 0, 8, 2)).setTo(1000);  // cell 2: a quarter bin 4, three quarters no reading
  const std::vector<float> f = rdsf.compute(image);
  EXPECT_NEAR(f[0], std::sqrt(0.5), 1e-6);                                    // (0,1)
  EXPECT_NEAR(f[1], std::sqrt(0.25), 1e-6);                                   // (0,2)
  EXPECT_NEAR(f[2], 0.0, 1e-6);                                               // (0,3): cell 3 is empty
  EXPECT_NEAR(f[127], std::sqrt(0.5 * 0.25) + std::sqrt(0.5 * 0.75), 1e-6);   // (1,2)
  EXPECT_NEAR(f[128], std::sqrt(0.5), 1e-6);                                  // (1,3)
  EXPECT_NEAR(f[8127], 1.0, 1e-6);                                            // (126,127)
  const cv::Mat1f h = rdsf.cell_histograms(image);
  EXPECT_FLOAT_EQ(h(1, 0), 0.5f);
  EXPECT_FLOAT_EQ(h(1, 4), 0.5f);
}

TEST(Rdsf, WrongCropSizeIsRefused) {
  const RdsfExtractor rdsf;
  EXPECT_THROW(rdsf.compute(cv::Mat1w(64, 64, std::uint16_t{0})), Error);
}
