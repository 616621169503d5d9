// The native Real AdaBoost rounds (depth 1, samples positives first: the trainer's fast path with
// several features' histograms at once) against a straightforward trainer written here from the header's
// definition: for every feature in whole blocks of four, per bin and class, the weights summed in sample
// order into two partial sums (even and odd positions within each class) then added, for the last
// features % 4 into four (position mod 4); the lowest Z wins (lowest feature on ties); the chosen
// feature's responses from the four-part sums; then the reweighting. The same Z bits, chosen features and
// response bits, round after round, for 1, 2 and 3 threads and feature counts with and without features
// left over after the blocks of four. (An eight-feature block was tried for issue 17 and was slower.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "classifier_support/toy_data.hpp"
#include "rdsf/classifier/real_adaboost.hpp"

namespace rdsf {
namespace {

struct ReferenceBooster {
  const BinnedMatrix& data;
  std::vector<int> labels;
  std::vector<double> w;
  std::vector<WeakClassifier> weak;
  std::vector<double> z_of_round;  // the chosen feature's Z: the bits of its two-part sums

  ReferenceBooster(const BinnedMatrix& d, std::vector<int> l)
      : data(d), labels(std::move(l)), w(labels.size(), 1.0 / static_cast<double>(labels.size())) {}

  // Per bin and class (2 * bin + y), weights summed in sample order into two partial sums by position
  // within the class, then added.
  std::vector<double> two_part_sums(std::size_t f, std::size_t positives) const {
    std::vector<double> part[2] = {std::vector<double>(2 * data.scheme().count, 0.0),
                                   std::vector<double>(2 * data.scheme().count, 0.0)};
    for (std::size_t i = 0; i < labels.size(); ++i) {
      const std::size_t begin = labels[i] == 1 ? 0 : positives;
      part[(i - begin) % 2][2 * data.at(f, i) + labels[i]] += w[i];
    }
    for (std::size_t j = 0; j < part[0].size(); ++j) part[0][j] += part[1][j];
    return part[0];
  }

  // ... into four partial sums by position mod 4 (the tail after the last block of four into the first),
  // added as (0 + 1) + (2 + 3).
  std::vector<double> four_part_sums(std::size_t f) const {
    const std::size_t n = labels.size();
    std::vector<double> part[4];
    for (auto& p : part) p.assign(2 * data.scheme().count, 0.0);
    for (std::size_t i = 0; i < n; ++i) part[i < n / 4 * 4 ? i % 4 : 0][2 * data.at(f, i) + labels[i]] += w[i];
    for (std::size_t j = 0; j < part[0].size(); ++j) part[0][j] = (part[0][j] + part[1][j]) + (part[2][j] + part[3][j]);
    return part[0];
  }

  void round() {
    const std::size_t n = labels.size();
    const int bins = data.scheme().count;
    std::size_t positives = 0;
    while (positives < n && labels[positives] == 1) ++positives;
    double best_z = std::numeric_limits<double>::infinity();
    std::size_t best_f = 0;
    // Features in whole blocks of four take the two-part sums; the last few (features % 4) the four-part.
    const std::size_t in_blocks = data.features() / 4 * 4;
    for (std::size_t f = 0; f < data.features(); ++f) {
      const std::vector<double> sums = f < in_blocks ? two_part_sums(f, positives) : four_part_sums(f);
      double z = 0.0;
      for (int j = 0; j < bins; ++j) z += std::sqrt(sums[2 * j] * sums[2 * j + 1]);
      z *= 2.0;
      if (z < best_z) {
        best_z = z;
        best_f = f;
      }
    }
    const std::vector<double> sums = four_part_sums(best_f);
    WeakClassifier h;
    h.feature = static_cast<int>(best_f);
    const double eps = 1.0 / static_cast<double>(n);
    for (int j = 0; j < bins; ++j) h.responses.push_back(0.5 * std::log((sums[2 * j + 1] + eps) / (sums[2 * j] + eps)));
    double total = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double r = h.responses[data.at(best_f, i)];
      w[i] *= std::exp(labels[i] == 1 ? -r : r);
      total += w[i];
    }
    for (double& x : w) x /= total;
    weak.push_back(h);
    z_of_round.push_back(best_z);
  }
};

TEST(RealAdaBoostReference, SameRoundsAsStraightforwardTrainer) {
  for (const int features : {19, 24, 37}) {
    std::mt19937 rng(static_cast<unsigned>(features));
    const int positives = 1001, negatives = 2500;
    cv::Mat1f rows(positives + negatives, features);
    std::vector<int> labels;
    for (int r = 0; r < rows.rows; ++r) {
      const int label = r < positives ? 1 : 0;
      labels.push_back(label);
      test::crowded_row(rng, rows, r, label);  // values crowd at 0 and 1 as RDSF values do
    }
    BinScheme scheme;
    scheme.count = 16;
    const BinnedMatrix matrix(rows, scheme);
    ReferenceBooster reference(matrix, labels);
    for (int round = 0; round < 12; ++round) reference.round();
    for (const int threads : {1, 2, 3}) {
      RealAdaBoostParams params;
      params.threads = threads;
      RealAdaBoost booster(matrix, labels, params);
      std::vector<double> z;
      for (int round = 0; round < 12; ++round) z.push_back(booster.next_round().z);
      EXPECT_EQ(std::memcmp(z.data(), reference.z_of_round.data(), z.size() * sizeof(double)), 0)
          << features << " features, " << threads << " threads";
      const auto& weak = booster.weak_classifiers();
      ASSERT_EQ(weak.size(), reference.weak.size());
      for (std::size_t k = 0; k < weak.size(); ++k) {
        ASSERT_EQ(weak[k].feature, reference.weak[k].feature) << features << " features, round " << k;
        ASSERT_EQ(weak[k].responses.size(), reference.weak[k].responses.size());
        EXPECT_EQ(std::memcmp(weak[k].responses.data(), reference.weak[k].responses.data(),
                              weak[k].responses.size() * sizeof(double)), 0)
            << features << " features, " << threads << " threads, round " << k;
      }
    }
  }
}

}  // namespace
}  // namespace rdsf
