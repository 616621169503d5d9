// Scoring only the features a model reads (ModelScorer, FeatureSubset) gives the full vector's scores bit
// for bit, in both feature specs; models and sample sets say which spec they use, and mismatches are refused.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "rdsf/classifier/features_read.hpp"
#include "rdsf/core/error.hpp"
#include "support/depth_scenes.hpp"
#include "support/test_support.hpp"
#include "rdsf/dataset/sample_set_manifest.hpp"
#include "rdsf/features/rdsf_extractor.hpp"
#include "rdsf/pipeline/mirror_scoring.hpp"
#include "rdsf/pipeline/model_scorer.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"

using namespace rdsf;
using rdsf::test::person_crop;

namespace {

BoostedModel random_model(const FeatureSpec& spec, int rounds, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> response(-1.0, 1.0);
  std::vector<WeakClassifier> weak;
  for (int r = 0; r < rounds; ++r) {
    WeakClassifier w;
    w.feature = static_cast<int>(random() % static_cast<unsigned>(spec.dimension()));
    if (r % 5 == 1) {  // a depth-2 tree of look-up tables: three nodes, three features
      w.kind = WeakClassifier::Kind::Tree;
      for (int k = 0; k < 3; ++k) {
        LutNode node;
        node.feature = k == 0 ? w.feature : static_cast<int>(random() % static_cast<unsigned>(spec.dimension()));
        for (int b = 0; b < 64; ++b) node.responses.push_back(response(random));
        w.nodes.push_back(node);
      }
    } else if (r % 7 == 3) {  // a stump now and then
      w.kind = WeakClassifier::Kind::Stump;
      w.threshold = 0.5;
      w.left = response(random);
      w.right = response(random);
    } else {
      for (int b = 0; b < 64; ++b) w.responses.push_back(response(random));
    }
    weak.push_back(w);
  }
  weak.push_back(weak.front());  // a feature read twice
  return BoostedModel(spec, BinScheme{}, weak);
}

using test::error_message;
const auto& error_of = error_message;

}  // namespace

TEST(FeaturesRead, AreTheWeakClassifiersFeaturesAscendingWithoutRepeats) {
  const BoostedModel model = random_model(FeatureSpec{}, 30, 1);
  const std::vector<int> read = features_read(model);
  EXPECT_TRUE(std::is_sorted(read.begin(), read.end()));
  EXPECT_EQ(std::adjacent_find(read.begin(), read.end()), read.end());
  std::size_t nodes = 0;
  for (const WeakClassifier& w : model.weak_classifiers()) {
    EXPECT_TRUE(std::binary_search(read.begin(), read.end(), w.feature));
    for (const LutNode& n : w.nodes) EXPECT_TRUE(std::binary_search(read.begin(), read.end(), n.feature));
    nodes += w.nodes.size();
  }
  EXPECT_GT(nodes, 0u);  // trees are among them
  EXPECT_LE(read.size(), 30u + nodes);
}

TEST(ModelScorer, ScoresEqualTheFullVectorsBitForBit) {
  for (const FeatureSpec& spec : {FeatureSpec{}, FeatureSpec::rect()}) {
    const RdsfExtractor extractor(spec);
    for (int rounds : {1, 100, 300}) {
      const BoostedModel model = random_model(spec, rounds, static_cast<unsigned>(rounds));
      const ModelScorer scorer(model);
      EXPECT_EQ(scorer.features().features(), features_read(model));  // trees read several
      for (unsigned seed = 0; seed < 6; ++seed) {
        const cv::Mat1w crop = person_crop(seed);
        const std::vector<float> full = extractor.compute(crop);
        EXPECT_EQ(scorer.score(crop), model.score(full.data())) << spec.name() << " rounds " << rounds;
        EXPECT_EQ(scorer.probability(crop), model.probability(model.score(full.data())));
      }
    }
  }
}

// The first k weak classifiers' sum from a crop's features (what an adapted model's inherited part needs,
// mirror_scoring.hpp) is bit for bit the score of a model of those k alone, with stumps (the model's own sum)
// and without (the binned forest's).
TEST(ModelScorer, TheFirstRoundsSumIsTheScoreOfAModelOfThoseRoundsAlone) {
  for (int rounds : {12, 100}) {
    BoostedModel model = random_model(FeatureSpec{}, rounds, 7u + static_cast<unsigned>(rounds));
    std::vector<WeakClassifier> lut_only;
    for (const WeakClassifier& w : model.weak_classifiers()) {
      if (w.kind != WeakClassifier::Kind::Stump) lut_only.push_back(w);
    }
    for (const BoostedModel& m : {model, BoostedModel(model.feature_spec(), model.bins(), lut_only)}) {
      const ModelScorer scorer(m);
      const bool binned = BinnedForest::supports(m);
      const RdsfExtractor extractor(m.feature_spec());
      for (std::size_t k : {std::size_t{0}, std::size_t{1}, m.weak_classifiers().size() / 2, m.weak_classifiers().size(),
                            m.weak_classifiers().size() + 5}) {
        const std::size_t kept = std::min(k, m.weak_classifiers().size());
        const std::vector<WeakClassifier> first(m.weak_classifiers().begin(),
                                                m.weak_classifiers().begin() + static_cast<std::ptrdiff_t>(kept));
        const ModelScorer alone(BoostedModel(m.feature_spec(), m.bins(), first));
        for (unsigned seed = 0; seed < 4; ++seed) {
          const cv::Mat1w crop = person_crop(seed);
          std::vector<float> values(static_cast<std::size_t>(scorer.features().size()));
          scorer.features().compute(crop, values.data());
          const std::vector<float> full = extractor.compute(crop);
          EXPECT_EQ(scorer.score_features(values.data(), k), alone.score(crop)) << "binned " << binned << " k " << k;
          EXPECT_EQ(m.score(full.data(), k), alone.score(crop)) << "k " << k;
        }
        if (k == 0) {
          EXPECT_EQ(alone.score(person_crop(0)), 0.0);
        }
      }
    }
  }
}

TEST(ModelScorer, ReferenceModelScoresCropsAsTheFullVectorDoes) {
  const std::string path = std::string(RDSF_SOURCE_DIR) + "/tests/reference_models/rdsf-model-v1-native.yml";
  const BoostedModel model = BoostedModel::load(path);
  EXPECT_EQ(model.feature_spec(), FeatureSpec{});  // written before rdsf-rect existed: still the thesis's spec
  const ModelScorer scorer(model);
  const RdsfExtractor extractor;
  for (unsigned seed = 10; seed < 20; ++seed) {
    const cv::Mat1w crop = person_crop(seed);
    EXPECT_EQ(scorer.score(crop), model.score(extractor.compute(crop).data()));
  }
}

TEST(ModelScorer, PipelineRefusesAModelOfAnotherSpecNamingBoth) {
  const BoostedModel rect_model = random_model(FeatureSpec::rect(), 5, 2);
  PipelineParams params;  // detector computes the thesis's features
  const std::string message = error_of([&] { PeoplePipeline pipeline(params, &rect_model); });
  EXPECT_NE(message.find("rdsf-rect/1"), std::string::npos) << message;
  EXPECT_NE(message.find("rdsf/1"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  params.analyser.features = FeatureSpec::rect();
  EXPECT_NO_THROW(PeoplePipeline(params, &rect_model));
}

TEST(SampleSetManifest, OldManifestsStillReadAndRectOnesRoundTrip) {
  // A manifest as the workbench wrote it before rdsf-rect (the fuzzing corpus keeps one).
  const std::string old_path = std::string(RDSF_SOURCE_DIR) + "/fuzz/corpus/manifest/kinect_v1.yml";
  std::ifstream in(old_path);
  std::stringstream text;
  text << in.rdbuf();
  const SampleSetManifest old = SampleSetManifest::parse(text.str(), old_path);
  EXPECT_EQ(old.feature_spec, FeatureSpec{});
  EXPECT_EQ(old.feature_spec.hash(), "48d0ea6f3a48b97c");

  SampleSetManifest rect = old;
  rect.feature_spec = FeatureSpec::parse("rdsf-rect:max=32");
  const SampleSetManifest again = SampleSetManifest::parse(rect.to_text(), "rect.yml");
  EXPECT_EQ(again.feature_spec, rect.feature_spec);
  EXPECT_EQ(again.feature_spec.rect_max_px, 32);

  std::string unknown = rect.to_text();
  unknown.replace(unknown.find("squares=8..32"), 13, "squares=8..33");
  const std::string message = error_of([&] { SampleSetManifest::parse(unknown, "unknown.yml"); });
  EXPECT_NE(message.find("unknown.yml: feature spec"), std::string::npos) << message;
  EXPECT_NE(message.find("not one this build knows"), std::string::npos) << message;
}

// Mirror averaging: mirrored_score is the score of the crop mirrored left to right, a crop that is its own
// mirror scores the same both ways, and MirrorScoring gives the mean of the two.
TEST(ModelScorer, MirroredScoreIsTheScoreOfTheMirroredCropAndAveragingTakesTheMean) {
  const BoostedModel model = random_model(FeatureSpec{}, 100, 7);
  const ModelScorer scorer(model);
  std::vector<Candidate> candidates;
  std::vector<double> scores;
  int differ = 0;
  for (unsigned seed = 0; seed < 6; ++seed) {
    Candidate c;
    c.depth_crop = person_crop(seed);
    c.depth_crop(cv::Rect(40, 30, 12, 40)).setTo(2500);  // an arm held out on one side: not its own mirror
    cv::Mat1w flipped;
    cv::flip(c.depth_crop, flipped, 1);
    EXPECT_EQ(scorer.mirrored_score(c.depth_crop), scorer.score(flipped));
    differ += scorer.mirrored_score(c.depth_crop) != scorer.score(c.depth_crop) ? 1 : 0;
    cv::Mat1w symmetric = c.depth_crop.clone();
    flipped(cv::Rect(0, 0, 32, 128)).copyTo(symmetric(cv::Rect(0, 0, 32, 128)));  // left half = right half mirrored
    EXPECT_EQ(scorer.mirrored_score(symmetric), scorer.score(symmetric));
    scores.push_back(scorer.score(c.depth_crop));
    candidates.push_back(c);
  }
  EXPECT_GT(differ, 0);  // the mirror is another view: the averaging below is not the identity
  std::vector<double> averaged = scores;
  MirrorScoring(model, PipelineParams{}).apply(scorer, candidates, cv::Mat1f(), cv::Mat1f(), averaged);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    EXPECT_EQ(averaged[i], 0.5 * (scores[i] + scorer.mirrored_score(candidates[i].depth_crop)));
  }
}

// The mirror's features read from the crop's own regions (both layouts at their defaults) are bit for bit
// those of the flipped crop; a spec whose regions are not each other's mirror images flips instead.
TEST(ModelScorer, TheMirrorsFeaturesFromTheCropsRegionsAreTheFlippedCropsBitForBit) {
  const FeatureSpec odd = FeatureSpec::parse("rdsf-rect:stride=24,max=16");  // 8 px squares at x 0, 24, 48
  for (const FeatureSpec& spec : {FeatureSpec{}, FeatureSpec::rect(), odd}) {
    for (int rounds : {3, 100, 300}) {
      const ModelScorer scorer(random_model(spec, rounds, 11u + static_cast<unsigned>(rounds)));
      EXPECT_EQ(scorer.mirrors_by_regions(), spec.layout == FeatureSpec::Layout::Cells || spec == FeatureSpec::rect())
          << spec.option_text();
      std::vector<float> crop_values(static_cast<std::size_t>(scorer.features().size())),
          mirror_values(crop_values.size()), flipped_values(crop_values.size()), plain(crop_values.size());
      for (unsigned seed = 0; seed < 8; ++seed) {
        cv::Mat1w crop = person_crop(seed);
        crop(cv::Rect(40, 30, 12, 40)).setTo(2500 + 100 * static_cast<int>(seed));  // not its own mirror
        if (seed % 3 == 0) crop(cv::Rect(0, 100, 20, 28)).setTo(9000);             // beyond the last bin
        cv::Mat1w flipped;
        cv::flip(crop, flipped, 1);
        scorer.compute_with_mirror(crop, crop_values.data(), mirror_values.data());
        scorer.features().compute(crop, plain.data());
        scorer.features().compute(flipped, flipped_values.data());
        for (std::size_t k = 0; k < plain.size(); ++k) {
          ASSERT_EQ(std::memcmp(&crop_values[k], &plain[k], sizeof(float)), 0) << spec.option_text() << " k " << k;
          ASSERT_EQ(std::memcmp(&mirror_values[k], &flipped_values[k], sizeof(float)), 0) << spec.option_text() << " k " << k;
        }
        EXPECT_EQ(scorer.mirrored_score(crop), scorer.score(flipped));
      }
    }
  }
}

// The pipeline scores a candidate by the mean of its crop's and its mirror's H(x) by default
// (PipelineParams::mirror_average), by its crop alone with it off, in both scoring paths (only the features
// the model reads, and the full vector); P(person) is the calibration of that score.
TEST(ModelScorer, PipelineScoresAreTheMeanOfTheCropAndItsMirrorByDefault) {
  const BoostedModel model = BoostedModel::load(std::string(RDSF_SOURCE_DIR) + "/models/people/v2.yml");
  const ModelScorer scorer(model);
  DepthFrame frame = test::wall_frame(4500);
  test::paint(frame, {300, 100, 40, 360}, 2000);  // a body
  test::paint(frame, {340, 180, 25, 12}, 2000);   // an arm held out to its left (the image's right)
  test::paint(frame, {120, 150, 30, 300}, 3000);  // a narrow post
  PipelineParams one_crop;
  one_crop.mirror_average = false;
  ASSERT_TRUE(PipelineParams{}.mirror_average);
  for (bool full : {false, true}) {
    PipelineParams averaged;
    averaged.full_feature_vector = full;
    one_crop.full_feature_vector = full;
    const PipelineFrame a = PeoplePipeline(averaged, &model).analyse(frame);
    const PipelineFrame b = PeoplePipeline(one_crop, &model).analyse(frame);
    ASSERT_GE(a.analysis.candidates.size(), 2u);
    ASSERT_EQ(a.scores.size(), b.scores.size());
    int differ = 0;
    for (std::size_t i = 0; i < a.scores.size(); ++i) {
      const cv::Mat1w& crop = a.analysis.candidates[i].depth_crop;
      EXPECT_EQ(b.scores[i], scorer.score(crop));
      EXPECT_EQ(a.scores[i], 0.5 * (scorer.score(crop) + scorer.mirrored_score(crop)));
      EXPECT_EQ(a.probabilities[i], model.probability(a.scores[i]));
      differ += a.scores[i] != b.scores[i] ? 1 : 0;
    }
    EXPECT_GT(differ, 0) << "full " << full;
  }
  // A model adapted to a room (rdsf-adapt records adapted_room) is scored by its crop alone.
  BoostedModel adapted = model;
  adapted.training().parameters.emplace_back("adapted_room", "/data/our-lab");
  EXPECT_TRUE(PipelineParams{}.mirror_average_for(model));
  EXPECT_FALSE(PipelineParams{}.mirror_average_for(adapted));
  EXPECT_FALSE(one_crop.mirror_average_for(model));
  const PipelineFrame c = PeoplePipeline(PipelineParams{}, &adapted).analyse(frame);
  for (std::size_t i = 0; i < c.scores.size(); ++i) {
    EXPECT_EQ(c.scores[i], scorer.score(c.analysis.candidates[i].depth_crop));
  }
}

// A model adapted to a room that records the rounds it continued (rdsf-train --init writes
// init_weak_classifiers) scores those mirror-averaged and its own on the crop alone by default
// (PipelineParams::mirror_average_inherited): H = (H_inh(crop) + H_inh(mirror)) / 2 + H_own(crop); with the
// option off, or without the record, the crop alone. Both scoring paths.
TEST(ModelScorer, AnAdaptedModelsInheritedRoundsAreMirrorAveragedItsOwnAreNot) {
  BoostedModel adapted = BoostedModel::load(std::string(RDSF_SOURCE_DIR) + "/models/people/v2.yml");
  constexpr std::size_t kInherited = 60;  // of its 100: the last 40 stand for the room's own rounds
  adapted.training().parameters.emplace_back("init_weak_classifiers", std::to_string(kInherited));
  adapted.training().parameters.emplace_back("adapted_room", "/data/our-lab");
  const std::vector<WeakClassifier> inherited_weak(adapted.weak_classifiers().begin(),
                                                   adapted.weak_classifiers().begin() + kInherited);
  const ModelScorer whole(adapted), inherited(BoostedModel(adapted.feature_spec(), adapted.bins(), inherited_weak));
  DepthFrame frame = test::wall_frame(4500);
  test::paint(frame, {300, 100, 40, 360}, 2000);  // a body
  test::paint(frame, {340, 180, 25, 12}, 2000);   // an arm held out to its left (the image's right)
  test::paint(frame, {120, 150, 30, 300}, 3000);  // a narrow post
  ASSERT_TRUE(PipelineParams{}.mirror_average_inherited);
  EXPECT_EQ(PipelineParams{}.inherited_mirror_rounds_for(adapted), kInherited);
  for (bool full : {false, true}) {
    PipelineParams on, off;
    on.full_feature_vector = off.full_feature_vector = full;
    off.mirror_average_inherited = false;
    const PipelineFrame a = PeoplePipeline(on, &adapted).analyse(frame);
    const PipelineFrame b = PeoplePipeline(off, &adapted).analyse(frame);
    ASSERT_GE(a.analysis.candidates.size(), 2u);
    int differ = 0;
    for (std::size_t i = 0; i < a.scores.size(); ++i) {
      const cv::Mat1w& crop = a.analysis.candidates[i].depth_crop;
      EXPECT_EQ(b.scores[i], whole.score(crop));
      EXPECT_EQ(a.scores[i], whole.score(crop) + 0.5 * (inherited.mirrored_score(crop) - inherited.score(crop)));
      EXPECT_EQ(a.probabilities[i], adapted.probability(a.scores[i]));
      differ += a.scores[i] != b.scores[i] ? 1 : 0;
    }
    EXPECT_GT(differ, 0) << "full " << full;
    // The further models of rdsf-detect: the crops' features kept from their scoring, or computed anew.
    const MirrorScoring mirror(adapted, on);
    ASSERT_TRUE(mirror.reads_mirror());
    cv::Mat1f kept, kept_mirror;
    whole.compute(a.analysis.candidates, kept, &kept_mirror);
    std::vector<double> given = whole.score_rows(kept), anew = whole.score(a.analysis.candidates);
    EXPECT_EQ(given, anew);  // the rows' scores are the crops'
    mirror.apply(whole, a.analysis.candidates, kept, kept_mirror, given);
    mirror.apply(whole, a.analysis.candidates, cv::Mat1f(), cv::Mat1f(), anew);
    EXPECT_EQ(given, a.scores);
    EXPECT_EQ(anew, a.scores);
    EXPECT_NE(error_of([&] { mirror.apply(whole, a.analysis.candidates, kept, kept_mirror.rowRange(0, 1), given); })
                  .find("mirror scoring: 1 rows of"),
              std::string::npos);
  }
  // Without the record nothing is known to be inherited: the crop alone, as before.
  BoostedModel unrecorded = adapted;
  unrecorded.training().parameters.clear();
  unrecorded.training().parameters.emplace_back("adapted_room", "/data/our-lab");
  EXPECT_EQ(PipelineParams{}.inherited_mirror_rounds_for(unrecorded), 0u);
  // A model that is not adapted is mirror-averaged whole (the rule above), nothing more.
  BoostedModel broad = adapted;
  broad.training().parameters.clear();
  EXPECT_EQ(PipelineParams{}.inherited_mirror_rounds_for(broad), 0u);
}
