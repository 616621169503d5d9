// rdsf-label with a model: the model answers the candidates it is sure about (journalled "by model" with its
// name, version and score, never shown), --ask uncertain presents the whole session closest to the model's
// operating point (P = 0.27 for people/v4) first, --budget stops after N human answers; a wrong model or
// thresholds change nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

std::string label() { return test::quote(test::program("rdsf-label")); }
std::string models() { return test::quote(std::string(RDSF_SOURCE_DIR) + "/models"); }
/// What `--model people` names: the newest shipped version.
const std::string kDefaultModel = "people/v4";
BoostedModel default_model() { return BoostedModel::load(std::string(RDSF_SOURCE_DIR) + "/models/" + kDefaultModel + ".yml"); }

struct Synth {
  test::TempDir dir;
  Synth() {
    const test::RunResult r = test::run(test::quote(test::program("rdsf-synth")) + " --out " + test::quote(dir / "synth") +
                                        " --frames 12 --people 1..2 --seed 3");
    EXPECT_EQ(r.exit_code, 0) << r.err;
  }
  test::RunResult label_with(const std::string& keys, const std::string& extra) const {
    std::ofstream(dir / "keys") << keys;
    return test::run(label() + " --source " + test::quote(dir / "synth") + " --out " + test::quote(dir / "set") +
                     " --models-dir " + models() + " --answers " + test::quote(dir / "keys") + " " + extra);
  }
};

std::vector<std::vector<std::string>> journal_rows(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream s(line);
    for (std::string x; std::getline(s, x, '\t');) f.push_back(x);
    rows.push_back(f);
  }
  return rows;
}

double field(const std::string& by, const std::string& key) {
  const auto at = by.find(key + "=");
  return at == std::string::npos ? NAN : std::stod(by.substr(at + key.size() + 1));
}

}  // namespace

TEST(LabelerModel, SureCandidatesAreAnsweredByTheModelAndJournalled) {
  Synth s;
  const test::RunResult r = s.label_with("", "--model people --accept 0.9 --reject 0.1 --keep-rejected");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const BoostedModel model = default_model();
  long by_model = 0;
  for (const auto& row : journal_rows(s.dir / "set/labeler-answers.tsv")) {
    ASSERT_EQ(row.size(), 10u);
    ASSERT_EQ(row[9].rfind("model " + kDefaultModel + " H=", 0), 0u) << row[9];  // only the model answered (keys: none)
    const double h = field(row[9], "H"), p = field(row[9], "P");
    EXPECT_NEAR(p, model.probability(h), 1e-3);
    EXPECT_TRUE(row[7] == "y" ? p >= 0.9 : p <= 0.1) << row[7] << " at P " << p;
    ++by_model;
  }
  ASSERT_GT(by_model, 0);
  const SampleSet set = SampleSet::open_read(s.dir / "set");
  ASSERT_EQ(static_cast<long>(set.records().size()), by_model);  // --keep-rejected: the n answers are stored too
  for (const SampleRecord& rec : set.records()) {
    EXPECT_EQ(rec.origin, "labeler-model");
    EXPECT_EQ(rec.model, kDefaultModel);
    ASSERT_TRUE(rec.score.has_value());
    EXPECT_TRUE(rec.label == 1 ? model.probability(*rec.score) >= 0.9 : model.probability(*rec.score) <= 0.1);
  }
  EXPECT_NE(r.err.find("by model: " + std::to_string(set.count(1)) + " positives, " + std::to_string(set.count(0)) +
                       " negatives"),
            std::string::npos)
      << r.err;
  // Nothing sure was asked: a rerun with every candidate answered n by the person stores only unsure ones.
  const test::RunResult asked = s.label_with(std::string(200, 'n'), "--model people --accept 0.9 --reject 0.1");
  ASSERT_EQ(asked.exit_code, 0) << asked.err;
  for (const auto& row : journal_rows(s.dir / "set/labeler-answers.tsv")) {
    if (row[9] != "human") continue;
    // The person's answers are the candidates the model was unsure of: their samples are not in the set,
    // so check by the model's score of the whole session instead: the rerun answered nothing by model.
    EXPECT_EQ(row[7], "n");
  }
  EXPECT_NE(asked.err.find("by model: 0 positives, 0 negatives"), std::string::npos) << asked.err;
  EXPECT_NE(asked.err.find(std::to_string(by_model) + " answered before"), std::string::npos) << asked.err;
}

TEST(LabelerModel, WithoutModelAnswersEveryCandidateIsAsked) {
  Synth s;
  const test::RunResult r = s.label_with("", "--model people --no-model-answers");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("by model: 0 positives, 0 negatives"), std::string::npos) << r.err;
  EXPECT_TRUE(journal_rows(s.dir / "set/labeler-answers.tsv").empty());
}

TEST(LabelerModel, AcceptBelowRejectIsAUsageErrorAndChangesNothing) {
  Synth s;
  const test::RunResult r = s.label_with("y", "--model people --accept 0.2 --reject 0.8");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--accept 0.2 must be at least --reject 0.8"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(s.dir / "set"));
}

TEST(LabelerModel, ModelOfAnotherFeatureSpecIsRefusedBeforeTheSetChanges) {
  Synth s;
  // A set of another spec (16 px cells) exists; the shipped model reads the thesis's.
  ASSERT_EQ(s.label_with("y q", "--feature-spec rdsf:cell=16").exit_code, 0);
  const auto before = std::filesystem::file_size(s.dir / "set/samples.tsv");
  const test::RunResult r = s.label_with("y y", "--feature-spec rdsf:cell=16 --model people");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(kDefaultModel + ".yml: the model reads feature spec"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the sample set"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(std::filesystem::file_size(s.dir / "set/samples.tsv"), before);
}

TEST(LabelerModel, AskUncertainPresentsTheWholeSessionClosestToTheOperatingPointFirstAndBudgetStops) {
  Synth s;
  const test::RunResult r = s.label_with(std::string(50, 'y'), "--model people --no-model-answers --ask uncertain --budget 6");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("answered 6 "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("budget of answers spent"), std::string::npos) << r.err;
  const BoostedModel model = default_model();
  // Uncertain is near where the model is read: people/v4 states P >= 0.27, not 0.5.
  const double boundary = model.operating_probability();
  EXPECT_EQ(boundary, 0.27);
  const SampleSet set = SampleSet::open_read(s.dir / "set");
  ASSERT_EQ(set.records().size(), 6u);
  std::vector<double> doubt;
  for (const SampleRecord& rec : set.records()) doubt.push_back(std::abs(model.probability(*rec.score) - boundary));
  EXPECT_TRUE(std::is_sorted(doubt.begin(), doubt.end()));
  // They are the six most uncertain of the session: the rest, labelled now, are all further from it.
  const test::RunResult rest = s.label_with(std::string(400, 'n'), "--model people --no-model-answers --keep-rejected");
  ASSERT_EQ(rest.exit_code, 0) << rest.err;
  const SampleSet all = SampleSet::open_read(s.dir / "set");
  ASSERT_GT(all.records().size(), 6u);
  for (std::size_t i = 6; i < all.records().size(); ++i) {
    EXPECT_GE(std::abs(model.probability(*all.records()[i].score) - boundary), doubt.back() - 1e-12);
  }
  EXPECT_NE(rest.err.find("6 answered before"), std::string::npos) << rest.err;
}

TEST(LabelerModel, AskUncertainNeedsAModel) {
  Synth s;
  const test::RunResult r = s.label_with("y", "--ask uncertain");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--ask uncertain needs --model"), std::string::npos) << r.err;
}

TEST(LabelerModel, AskUncertainGivesTheSameSessionOnEveryThreadCount) {
  // The whole session is analysed and scored on --threads workers before the first question, in frame
  // order: the questions, and so the stored samples, must not depend on the count.
  auto stored = [](const Synth& s) {
    std::vector<std::string> rows;
    const SampleSet set = SampleSet::open_read(s.dir / "set");
    for (const SampleRecord& r : set.records()) {
      std::ostringstream row;
      row << r.frame << ' ' << r.strict_box << ' ' << r.label << ' ' << r.origin << ' ' << r.score.value_or(NAN);
      rows.push_back(row.str());
    }
    return rows;
  };
  Synth one, three;
  const test::RunResult a = one.label_with(std::string(8, 'y'), "--model people --ask uncertain --budget 8 --threads 1");
  const test::RunResult b = three.label_with(std::string(8, 'y'), "--model people --ask uncertain --budget 8 --threads 3");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const std::vector<std::string> rows = stored(one);
  EXPECT_GE(rows.size(), 8u);  // the eight answers, plus what the model answered
  EXPECT_EQ(rows, stored(three));
}

// --ask likely presents the whole session highest P(person) first; --only-added-by leaves out the candidates
// the same options without the option make too (what is stored are candidates only the option adds), and
// refuses an option at its default or a name that is no analyser option.
TEST(LabelerModel, AskLikelyAndOnlyWhatAnOptionAdds) {
  Synth s;
  const test::RunResult r = s.label_with(std::string(50, 'y'), "--model people --no-model-answers --ask likely --budget 5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const BoostedModel model = default_model();
  const SampleSet set = SampleSet::open_read(s.dir / "set");
  ASSERT_EQ(set.records().size(), 5u);
  std::vector<double> p;
  for (const SampleRecord& rec : set.records()) p.push_back(model.probability(*rec.score));
  EXPECT_TRUE(std::is_sorted(p.rbegin(), p.rend()));  // the likeliest first
  std::filesystem::remove_all(s.dir / "set");

  // --occlusion-gap 0 (the default 60) makes other candidates; only those no candidate of the default matches.
  const test::RunResult added = s.label_with(std::string(400, 'n'),
                                             "--model people --no-model-answers --keep-rejected --occlusion-gap 0 "
                                             "--only-added-by occlusion-gap");
  ASSERT_EQ(added.exit_code, 0) << added.err;
  EXPECT_NE(added.err.find("only what --occlusion-gap adds: "), std::string::npos) << added.err;
  const test::RunResult all = test::run(label() + " --source " + test::quote(s.dir / "synth") + " --out " +
                                        test::quote(s.dir / "all") + " --models-dir " + models() +
                                        " --answers " + test::quote(s.dir / "keys") +
                                        " --model people --no-model-answers --keep-rejected --occlusion-gap 0");
  ASSERT_EQ(all.exit_code, 0) << all.err;
  const std::size_t only = SampleSet::open_read(s.dir / "set").records().size();
  EXPECT_LT(only, SampleSet::open_read(s.dir / "all").records().size());  // some were left out

  for (const char* bad : {"--only-added-by occlusion-gap", "--only-added-by frobnicate --occlusion-gap 0"}) {
    const test::RunResult refused = s.label_with("y", std::string("--model people ") + bad);
    EXPECT_EQ(refused.exit_code, 2) << bad << ": " << refused.err;
    EXPECT_NE(refused.err.find("--only-added-by"), std::string::npos) << refused.err;
  }
}
