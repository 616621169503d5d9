// The full RDSF vector (RdsfExtractor::compute, computed region j by region j for all i < j at once)
// against the straightforward loop it replaced: pair_value(h, i, j) for i < j in order. The same bits for
// every feature, for the thesis's cells and the paper's rectangles, on random crops (noise, steps, missing
// readings, several bin widths) and on the crops of synthetic candidates.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/features/rdsf_extractor.hpp"
#include "rdsf/synth/synth_sequence.hpp"

namespace rdsf {
namespace {

std::vector<float> reference_vector(const FeatureSpec& spec, const cv::Mat1w& crop) {
  RegionHistogramBuilder builder(spec);
  RootHistograms h;
  builder.compute_all(crop, h);
  std::vector<float> out;
  const int n = spec.region_count();
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) out.push_back(pair_value(h, i, j));
  }
  return out;
}

void expect_same_bits(const FeatureSpec& spec, const cv::Mat1w& crop, const std::string& what) {
  const std::vector<float> fast = RdsfExtractor(spec).compute(crop);
  const std::vector<float> reference = reference_vector(spec, crop);
  ASSERT_EQ(fast.size(), reference.size()) << what;
  std::size_t differ = 0;
  for (std::size_t k = 0; k < fast.size(); ++k) differ += std::memcmp(&fast[k], &reference[k], sizeof(float)) != 0;
  EXPECT_EQ(differ, 0U) << what;
}

cv::Mat1w random_crop(std::mt19937& rng, int kind) {
  cv::Mat1w crop(128, 64);
  std::uniform_int_distribution<int> depth(1, 9000);
  const int a = depth(rng), b = depth(rng), c = depth(rng);
  for (int y = 0; y < 128; ++y) {
    for (int x = 0; x < 64; ++x) {
      int v = 0;
      if (kind == 0) v = depth(rng);                                        // noise
      if (kind == 1) v = (x < 20 + y / 8) ? a : (y > 90 ? b : c);           // steps
      if (kind == 2) v = (rng() % 5 == 0) ? 0 : a + static_cast<int>(rng() % 600);  // a body with holes
      crop(y, x) = static_cast<std::uint16_t>(v);
    }
  }
  return crop;
}

TEST(RdsfReference, SameBitsOnRandomCrops) {
  std::mt19937 rng(4);
  FeatureSpec coarse = FeatureSpec::thesis();
  coarse.bin_width_mm = 1000;  // fewer bins: more regions of one bin
  coarse.max_depth_mm = 9000;
  for (const FeatureSpec& spec : {FeatureSpec::thesis(), coarse, FeatureSpec::rect()}) {
    for (int trial = 0; trial < 9; ++trial) {
      expect_same_bits(spec, random_crop(rng, trial % 3), spec.name() + " trial " + std::to_string(trial));
    }
    expect_same_bits(spec, cv::Mat1w::zeros(128, 64), spec.name() + " empty crop");
  }
}

TEST(RdsfReference, SameBitsOnSyntheticCandidates) {
  const synth::SynthParams p = synth::people_scene(3, 2, 4, 9);
  synth::SynthSequence sequence(p);
  const FrameAnalyser analyser{AnalyserParams{}};
  int crops = 0;
  for (int i = 0; i < 3; ++i) {
    DepthFrame frame;
    frame.depth_mm = sequence.frame(i).depth_mm;
    for (const Candidate& c : analyser.analyse(frame, false).candidates) {
      expect_same_bits(FeatureSpec::thesis(), c.depth_crop, "candidate " + std::to_string(crops++));
    }
  }
  EXPECT_GT(crops, 3);
}

}  // namespace
}  // namespace rdsf
