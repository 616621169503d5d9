// The native Real AdaBoost rounds with trees (depth 2 and 3), weight trimming, shrinkage and samples in
// any class order, against a straightforward trainer written here from real_adaboost.hpp: node by node,
// every feature's sums taken one feature at a time over the node's samples in sample order into four
// partial sums by position (the tail after the last block of four into the first), added as (0 + 1) +
// (2 + 3); at the root of an untrimmed round with the samples positives first, the features in whole
// blocks of four take two partial sums by position within each class instead (as
// test_real_adaboost_reference states). The same Z bits, features and table bits, round after round, for
// 1 and 3 threads. (Issue 17 made the nodes of a level share one pass over the bins.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>

#include "classifier_support/toy_data.hpp"
#include "rdsf/classifier/real_adaboost.hpp"

namespace rdsf {
namespace {

struct ReferenceTrees {
  const BinnedMatrix& data;
  std::vector<int> labels;
  RealAdaBoostParams params;
  std::vector<double> w;
  std::vector<WeakClassifier> weak;
  std::vector<double> z_of_round;

  ReferenceTrees(const BinnedMatrix& d, std::vector<int> l, RealAdaBoostParams p)
      : data(d), labels(std::move(l)), params(p), w(labels.size(), 1.0 / static_cast<double>(labels.size())) {}

  int bins() const { return data.scheme().count; }

  std::vector<double> four_part_sums(std::size_t f, const std::vector<std::size_t>& members) const {
    std::vector<double> part[4];
    for (auto& p : part) p.assign(2 * bins(), 0.0);
    const std::size_t whole = members.size() / 4 * 4;
    for (std::size_t k = 0; k < members.size(); ++k) {
      const std::size_t i = members[k];
      part[k < whole ? k % 4 : 0][2 * data.at(f, i) + labels[i]] += w[i];
    }
    for (std::size_t j = 0; j < part[0].size(); ++j) part[0][j] = (part[0][j] + part[1][j]) + (part[2][j] + part[3][j]);
    return part[0];
  }

  std::vector<double> two_part_sums(std::size_t f, std::size_t positives) const {
    std::vector<double> part[2] = {std::vector<double>(2 * bins(), 0.0), std::vector<double>(2 * bins(), 0.0)};
    for (std::size_t i = 0; i < labels.size(); ++i) {
      const std::size_t begin = labels[i] == 1 ? 0 : positives;
      part[(i - begin) % 2][2 * data.at(f, i) + labels[i]] += w[i];
    }
    for (std::size_t j = 0; j < part[0].size(); ++j) part[0][j] += part[1][j];
    return part[0];
  }

  // Z of a split and its threshold (lowest of equals), or Z of a table.
  std::pair<double, int> z_of(const std::vector<double>& s, bool split) const {
    if (!split) {
      double z = 0.0;
      for (int j = 0; j < bins(); ++j) z += std::sqrt(s[2 * j] * s[2 * j + 1]);
      return {2.0 * z, 0};
    }
    double tp = 0.0, tn = 0.0;
    for (int j = 0; j < bins(); ++j) {
      tn += s[2 * j];
      tp += s[2 * j + 1];
    }
    double lp = 0.0, ln = 0.0, best = std::numeric_limits<double>::infinity();
    int best_t = 0;
    for (int t = 0; t + 1 < bins(); ++t) {
      ln += s[2 * t];
      lp += s[2 * t + 1];
      const double z = 2.0 * (std::sqrt(lp * ln) + std::sqrt(std::max(0.0, tp - lp) * std::max(0.0, tn - ln)));
      if (z < best) {
        best = z;
        best_t = t;
      }
    }
    return {best, best_t};
  }

  // The best table or split of one node; `two_part` for the untrimmed root with positives first.
  LutNode fit(const std::vector<std::size_t>& members, bool two_part, bool split, double& z_out) const {
    std::size_t positives = 0;
    while (positives < labels.size() && labels[positives] == 1) ++positives;
    const std::size_t in_blocks = data.features() / 4 * 4;
    double best_z = std::numeric_limits<double>::infinity();
    std::size_t best_f = 0;
    for (std::size_t f = 0; f < data.features(); ++f) {
      const double z =
          z_of(two_part && f < in_blocks ? two_part_sums(f, positives) : four_part_sums(f, members), split).first;
      if (z < best_z) {
        best_z = z;
        best_f = f;
      }
    }
    const std::vector<double> s = four_part_sums(best_f, members);
    LutNode node;
    node.feature = static_cast<int>(best_f);
    const double eps = 1.0 / static_cast<double>(labels.size());
    const int t = z_of(s, true).second;
    for (int j = 0; j < bins(); ++j) {
      node.responses.push_back(split ? (j <= t ? -1.0 : 1.0) : 0.5 * std::log((s[2 * j + 1] + eps) / (s[2 * j] + eps)));
    }
    z_out = best_z;
    return node;
  }

  void round() {
    const std::size_t n = labels.size();
    const bool sorted = std::is_sorted(labels.begin(), labels.end(), [](int a, int b) { return a > b; });
    std::vector<std::size_t> used(n);
    std::iota(used.begin(), used.end(), std::size_t{0});
    if (params.weight_trim > 0.0) {
      std::stable_sort(used.begin(), used.end(), [&](std::size_t a, std::size_t b) { return w[a] > w[b]; });
      double mass = 0.0;
      std::size_t count = 0;
      while (count < n && mass < 1.0 - params.weight_trim) mass += w[used[count++]];
      used.resize(count);
      std::sort(used.begin(), used.end());
    }
    const bool untrimmed = params.weight_trim == 0.0;
    const std::size_t node_count = (std::size_t{1} << params.depth) - 1, first_leaf = node_count / 2;
    WeakClassifier h;
    h.kind = WeakClassifier::Kind::Tree;
    h.nodes.resize(node_count);
    std::vector<std::size_t> node_of(n, 0);
    double z = 0.0;
    for (std::size_t k = 0; k < node_count; ++k) {
      std::vector<std::size_t> members;
      for (std::size_t i : used) {
        if (node_of[i] == k) members.push_back(i);
      }
      double mass = 0.0;
      for (std::size_t i : members) mass += w[i];
      if (k > 0 && mass <= 1e-12) {
        h.nodes[k].feature = h.nodes[(k - 1) / 2].feature;
        h.nodes[k].responses.assign(static_cast<std::size_t>(bins()), k < first_leaf ? -1.0 : 0.0);
      } else {
        double node_z = 0.0;
        h.nodes[k] = fit(members, k == 0 && untrimmed && sorted, k < first_leaf, node_z);
        if (k >= first_leaf) z += node_z;
      }
      if (k < first_leaf) {
        for (std::size_t i = 0; i < n; ++i) {
          if (node_of[i] != k) continue;
          node_of[i] = 2 * k + (h.nodes[k].responses[data.at(static_cast<std::size_t>(h.nodes[k].feature), i)] > 0.0 ? 2 : 1);
        }
      }
    }
    for (std::size_t k = first_leaf; k < node_count; ++k) {
      for (double& r : h.nodes[k].responses) r *= params.learning_rate;
    }
    double total = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const LutNode& leaf = h.nodes[node_of[i]];
      const double r = leaf.responses[data.at(static_cast<std::size_t>(leaf.feature), i)];
      w[i] *= std::exp(labels[i] == 1 ? -r : r);
      total += w[i];
    }
    for (double& x : w) x /= total;
    h.feature = h.nodes[0].feature;
    weak.push_back(h);
    z_of_round.push_back(z);
  }
};

// n crowded rows (test::crowded_row) of `features` values: the first `positives` are people when
// positives >= 0, else one row in three at random.
test::ToyData crowded_rows(int n, int features, unsigned seed, int positives) {
  std::mt19937 rng(seed);
  test::ToyData d;
  d.rows.create(n, features);
  for (int r = 0; r < n; ++r) {
    d.labels.push_back(positives >= 0 ? (r < positives ? 1 : 0) : (rng() % 3 == 0 ? 1 : 0));
    test::crowded_row(rng, d.rows, r, d.labels.back());
  }
  return d;
}

TEST(RealAdaBoostTreeReference, SameTreesAsStraightforwardTrainer) {
  for (const bool sorted : {true, false}) {
    for (const int bin_count : {16, 64}) {
      const test::ToyData d = crowded_rows(1403, 19, static_cast<unsigned>(bin_count + sorted), sorted ? 401 : -1);
      const cv::Mat1f& rows = d.rows;
      const std::vector<int>& labels = d.labels;
      BinScheme scheme;
      scheme.count = bin_count;
      const BinnedMatrix matrix(rows, scheme);
      for (const int depth : {2, 3}) {
        for (const double trim : {0.0, 0.1}) {
          RealAdaBoostParams params;
          params.depth = depth;
          params.weight_trim = trim;
          params.learning_rate = 0.5;
          ReferenceTrees reference(matrix, labels, params);
          for (int round = 0; round < 5; ++round) reference.round();
          for (const int threads : {1, 3}) {
            params.threads = threads;
            RealAdaBoost booster(matrix, labels, params);
            std::vector<double> z;
            for (int round = 0; round < 5; ++round) z.push_back(booster.next_round().z);
            const std::string what = std::string(sorted ? "positives first" : "classes mixed") + ", " +
                                     std::to_string(bin_count) + " bins, depth " + std::to_string(depth) + ", trim " +
                                     std::to_string(trim) + ", " + std::to_string(threads) + " threads";
            EXPECT_EQ(std::memcmp(z.data(), reference.z_of_round.data(), z.size() * sizeof(double)), 0) << what;
            const auto& weak = booster.weak_classifiers();
            ASSERT_EQ(weak.size(), reference.weak.size());
            for (std::size_t k = 0; k < weak.size(); ++k) {
              EXPECT_TRUE(weak[k] == reference.weak[k]) << what << ", round " << k;
            }
          }
        }
      }
    }
  }
}

TEST(RealAdaBoostTreeReference, TrimmedStumpsAsStraightforwardTrainer) {
  // Depth 1 with trimming: the one node is the trimmed sample list (four-part sums).
  const int n = 997;
  const test::ToyData d = crowded_rows(n, 13, 5, 300);
  const std::vector<int>& labels = d.labels;
  const BinnedMatrix matrix(d.rows, BinScheme{});
  RealAdaBoostParams params;
  params.weight_trim = 0.2;
  params.threads = 2;
  RealAdaBoost booster(matrix, labels, params);
  ReferenceTrees reference(matrix, labels, params);
  for (int round = 0; round < 6; ++round) {
    const RealAdaBoostRound got = booster.next_round();
    // The reference grows a one-node tree: the same table as a depth-1 look-up table.
    reference.params.depth = 1;
    reference.round();
    const WeakClassifier& mine = booster.weak_classifiers().back();
    const LutNode& theirs = reference.weak.back().nodes[0];
    EXPECT_EQ(mine.feature, theirs.feature) << "round " << round;
    EXPECT_EQ(std::memcmp(mine.responses.data(), theirs.responses.data(), mine.responses.size() * sizeof(double)), 0)
        << "round " << round;
    EXPECT_EQ(std::memcmp(&got.z, &reference.z_of_round.back(), sizeof(double)), 0) << "round " << round;
    EXPECT_LT(got.samples_used, static_cast<std::size_t>(n));
  }
}

TEST(RealAdaBoostTreeReference, HistogramSubtractionChangesOnlyTheRounding) {
  // Subtraction changes the sums that choose the features by rounding only; the chosen features' tables
  // are summed directly. On these rows (no near ties) the trees are the same bits and Z agrees to
  // rounding; at depth 1 the option does nothing.
  const test::ToyData d = crowded_rows(1501, 23, 11, -1);
  const std::vector<int>& labels = d.labels;
  const BinnedMatrix matrix(d.rows, BinScheme{});
  for (const int depth : {1, 2, 3}) {
    for (const double trim : {0.0, 0.1}) {
      RealAdaBoostParams params;
      params.depth = depth;
      params.weight_trim = trim;
      params.threads = 2;
      RealAdaBoost exact(matrix, labels, params);
      params.histogram_subtraction = true;
      RealAdaBoost subtracted(matrix, labels, params);
      for (int round = 0; round < 6; ++round) {
        const RealAdaBoostRound a = exact.next_round(), b = subtracted.next_round();
        if (depth == 1) {
          EXPECT_EQ(std::memcmp(&a.z, &b.z, sizeof(double)), 0) << "round " << round;
        } else {
          EXPECT_NEAR(a.z, b.z, 1e-12) << "depth " << depth << ", trim " << trim << ", round " << round;
        }
        EXPECT_TRUE(exact.weak_classifiers().back() == subtracted.weak_classifiers().back())
            << "depth " << depth << ", trim " << trim << ", round " << round;
      }
    }
  }
}

}  // namespace
}  // namespace rdsf
