// BinnedForest (flat tables over a binned row) scores bit for bit as BoostedModel::score: random models
// of look-up tables and trees of depth 2-4 on rows with values at and around the bin edges, the shipped
// model on random rows; models with stumps are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "rdsf/classifier/binned_forest.hpp"
#include "rdsf/classifier/features_read.hpp"
#include "rdsf/core/error.hpp"

using namespace rdsf;

namespace {

std::uint64_t bits_of(double d) {
  std::uint64_t b = 0;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

BoostedModel random_model(int row_size, const BinScheme& bins, int rounds, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> response(-1.0, 1.0);
  auto feature = [&] { return static_cast<int>(random() % static_cast<unsigned>(row_size)); };
  auto table = [&] {
    std::vector<double> t;
    for (int b = 0; b < bins.count; ++b) t.push_back(random() % 9 == 0 ? 0.0 : response(random));  // zeros: left
    return t;
  };
  std::vector<WeakClassifier> weak;
  for (int r = 0; r < rounds; ++r) {
    WeakClassifier w;
    if (r % 4 == 0) {
      w.feature = feature();
      w.responses = table();
    } else {
      w.kind = WeakClassifier::Kind::Tree;
      const int nodes = (1 << (2 + r % 3)) - 1;  // depths 2, 3, 4
      for (int k = 0; k < nodes; ++k) w.nodes.push_back({feature(), table()});
      w.feature = w.nodes[0].feature;
    }
    weak.push_back(w);
  }
  FeatureSpec spec;  // "rdsf": 8128 features, more than any row here
  return BoostedModel(spec, bins, weak);
}

std::vector<float> random_row(int n, const BinScheme& bins, std::mt19937& random) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> row;
  for (int k = 0; k < n; ++k) {
    float v = unit(random);
    if (random() % 3 == 0) v = bins.lower_edge(static_cast<int>(random() % static_cast<unsigned>(bins.count + 1)));
    if (random() % 5 == 0) v = std::nextafter(v, random() % 2 ? 2.0f : -1.0f);
    if (random() % 50 == 0) v = random() % 2 ? 1.0f : 0.0f;
    row.push_back(v);
  }
  return row;
}

TEST(BinnedForest, SameBitsAsTheModelOnRandomModels) {
  for (const BinScheme& bins : {BinScheme{32, 0.0f, 1.0f}, BinScheme{64, 0.0f, 1.0f}, BinScheme{13, 0.1f, 0.9f}}) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
      const int row_size = 37 + static_cast<int>(seed) * 61;
      const BoostedModel model = random_model(row_size, bins, 120, seed);
      const BinnedForest forest(model, row_size);
      std::mt19937 random(seed * 7);
      for (int r = 0; r < 300; ++r) {
        const std::vector<float> row = random_row(row_size, bins, random);
        ASSERT_EQ(bits_of(forest.score(row.data())), bits_of(model.score(row.data()))) << "seed " << seed << " row " << r;
      }
    }
  }
}

// The forest over the features a shipped model reads scores random rows with the model's bits.
void same_bits_as_the_shipped_model(const std::string& path) {
  const BoostedModel model = BoostedModel::load(path);
  ASSERT_TRUE(BinnedForest::supports(model));
  std::vector<WeakClassifier> weak = model.weak_classifiers();
  const std::vector<int> read = features_read(model);
  renumber_features(weak, [&](int f) {
    return static_cast<int>(std::lower_bound(read.begin(), read.end(), f) - read.begin());
  });
  const BoostedModel compact(model.feature_spec(), model.bins(), weak);
  const BinnedForest forest(compact, static_cast<int>(read.size()));
  std::mt19937 random(17);
  for (int r = 0; r < 2000; ++r) {
    const std::vector<float> row = random_row(static_cast<int>(read.size()), model.bins(), random);
    ASSERT_EQ(bits_of(forest.score(row.data())), bits_of(compact.score(row.data()))) << "row " << r;
  }
}

TEST(BinnedForest, SameBitsAsTheShippedModels) {
  for (const char* version : {"v1", "v2"}) {
    SCOPED_TRACE(version);
    same_bits_as_the_shipped_model(std::string(RDSF_SOURCE_DIR) + "/models/people/" + version + ".yml");
  }
}
TEST(BinnedForest, RefusesStumpsAndFeaturesOutsideTheRow) {
  BoostedModel model = random_model(50, BinScheme{}, 10, 3);
  EXPECT_THROW(BinnedForest(model, 20), Error);
  std::vector<WeakClassifier> weak = model.weak_classifiers();
  WeakClassifier stump;
  stump.kind = WeakClassifier::Kind::Stump;
  weak.push_back(stump);
  const BoostedModel with_stump(model.feature_spec(), model.bins(), weak);
  EXPECT_FALSE(BinnedForest::supports(with_stump));
  EXPECT_THROW(BinnedForest(with_stump, 50), Error);
}

}  // namespace
