// The histogram kernels of bin_histograms.hpp against straightforward loops written here from the header:
// the same bits for every feature count of a pass, bin count (a 64-bin stride and the 256-bin one), class
// sizes that leave tails after the blocks of eight samples, and nodes with and without samples of no node.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "rdsf/classifier/bin_histograms.hpp"

namespace rdsf {
namespace {

struct Rows {
  std::vector<std::vector<std::uint8_t>> bins;  // per feature
  std::vector<std::uint8_t> y;
  std::vector<double> w;
};

// `features` rows of n bins crowding at the top bin as RDSF values do, positives first, random weights.
Rows make_rows(int features, std::size_t positives, std::size_t n, int bin_count, unsigned seed) {
  std::mt19937 rng(seed);
  Rows r;
  for (int f = 0; f < features; ++f) {
    std::vector<std::uint8_t> b(n);
    for (auto& v : b) v = static_cast<std::uint8_t>(rng() % 3 == 0 ? bin_count - 1 : rng() % bin_count);
    r.bins.push_back(b);
  }
  for (std::size_t i = 0; i < n; ++i) {
    r.y.push_back(i < positives ? 1 : 0);
    r.w.push_back(std::uniform_real_distribution<double>(1e-6, 1e-3)(rng));
  }
  return r;
}

std::vector<double> straightforward_two_part(const std::vector<std::uint8_t>& bins, const Rows& r,
                                             std::size_t positives, int bin_count) {
  std::vector<double> even(2 * bin_count, 0.0), odd(2 * bin_count, 0.0);
  for (std::size_t i = 0; i < bins.size(); ++i) {
    const std::size_t position = r.y[i] == 1 ? i : i - positives;
    (position % 2 == 0 ? even : odd)[2 * bins[i] + r.y[i]] += r.w[i];
  }
  for (std::size_t j = 0; j < even.size(); ++j) even[j] += odd[j];
  return even;
}

std::vector<double> straightforward_four_part(const std::vector<std::uint8_t>& bins, const Rows& r,
                                              const std::vector<std::size_t>& members, int bin_count) {
  std::vector<double> part[4];
  for (auto& p : part) p.assign(2 * bin_count, 0.0);
  const std::size_t whole = members.size() / 4 * 4;
  for (std::size_t k = 0; k < members.size(); ++k) {
    const std::size_t i = members[k];
    part[k < whole ? k % 4 : 0][2 * bins[i] + r.y[i]] += r.w[i];
  }
  for (std::size_t j = 0; j < part[0].size(); ++j) part[0][j] = (part[0][j] + part[1][j]) + (part[2][j] + part[3][j]);
  return part[0];
}

bool same_bits(const double* a, const std::vector<double>& b) {
  return std::memcmp(a, b.data(), b.size() * sizeof(double)) == 0;
}

TEST(BinHistograms, TwoPartSumsAsStraightforwardLoop) {
  for (const int bin_count : {16, 64, 200}) {
    for (const std::size_t positives : {std::size_t{37}, std::size_t{64}, std::size_t{301}}) {
      const std::size_t n = positives + 517;
      const Rows r = make_rows(8, positives, n, bin_count, static_cast<unsigned>(bin_count + positives));
      for (const int count : {1, 3, 4, 8}) {
        const std::uint8_t* bins[8];
        std::vector<std::vector<double>> sums(8, std::vector<double>(2 * bin_count, -1.0));
        double* out[8];
        for (int f = 0; f < count; ++f) {
          bins[f] = r.bins[static_cast<std::size_t>(f)].data();
          out[f] = sums[static_cast<std::size_t>(f)].data();
        }
        two_part_histograms(bins, count, r.w.data(), positives, n, bin_count, out);
        for (int f = 0; f < count; ++f) {
          EXPECT_TRUE(same_bits(out[f], straightforward_two_part(r.bins[static_cast<std::size_t>(f)], r, positives, bin_count)))
              << bin_count << " bins, " << positives << " positives, " << count << " features, feature " << f;
        }
      }
    }
  }
}

TEST(BinHistograms, NodeSumsAsStraightforwardLoop) {
  for (const int bin_count : {16, 64, 200}) {
    const std::size_t positives = 211, n = 1203;
    Rows r = make_rows(4, positives, n, bin_count, static_cast<unsigned>(bin_count));
    // Shuffle the classes: node sums do not need positives first.
    std::mt19937 rng(7);
    for (auto& c : r.y) c = static_cast<std::uint8_t>(rng() % 4 == 0);
    for (const std::size_t node_count : {std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{8}}) {
      for (const bool everyone : {true, false}) {
        std::vector<std::vector<std::size_t>> members(node_count);
        for (std::size_t i = 0; i < n; ++i) {
          if (!everyone && rng() % 5 == 0) continue;  // in no node (trimmed)
          members[rng() % node_count].push_back(i);
        }
        std::vector<const std::vector<std::size_t>*> lists;
        for (const auto& m : members) lists.push_back(&m);
        NodeSamples samples(lists, r.y, n);
        EXPECT_EQ(samples.dense(), everyone);
        samples.gather_weights(r.w);
        for (const int count : {1, 2, 3, 4}) {
          const std::uint8_t* bins[4];
          std::vector<std::vector<double>> sums(4 * node_count, std::vector<double>(2 * bin_count, -1.0));
          double* out[32];
          for (int f = 0; f < count; ++f) bins[f] = r.bins[static_cast<std::size_t>(f)].data();
          for (std::size_t k = 0; k < sums.size(); ++k) out[k] = sums[k].data();
          node_histograms(bins, count, samples, bin_count, out);
          for (int f = 0; f < count; ++f) {
            for (std::size_t node = 0; node < node_count; ++node) {
              EXPECT_TRUE(same_bits(out[static_cast<std::size_t>(f) * node_count + node],
                                    straightforward_four_part(r.bins[static_cast<std::size_t>(f)], r, members[node], bin_count)))
                  << bin_count << " bins, " << node_count << " nodes, " << count << " features, feature " << f
                  << ", node " << node << (everyone ? "" : ", some samples in no node");
            }
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace rdsf
