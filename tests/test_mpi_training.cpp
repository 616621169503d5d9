// rdsf-train under mpirun (issue 37): the rows split over 2 and 3 ranks train the model the one-process
// run trains (folds, calibration and augmentation included); a rank that cannot read its share, ranks
// with other options and a rank killed mid-run end every rank with an error and leave no model. Started
// with the real mpirun; skipped with a message when mpirun is absent or this build has no MPI.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "classifier_support/toy_sets.hpp"
#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/version.hpp"
#include "support/test_support.hpp"

namespace rdsf {
namespace {

namespace fs = std::filesystem;

#define RDSF_REQUIRE_MPIRUN()                                                                            \
  do {                                                                                                   \
    if (!RDSF_WITH_MPI) GTEST_SKIP() << "built without MPI (RDSF_WITH_MPI=OFF): data-parallel test skipped"; \
    if (test::run("command -v mpirun").exit_code != 0)                                                   \
      GTEST_SKIP() << "mpirun is absent (Debian: openmpi-bin): data-parallel test skipped";              \
  } while (0)

// mpirun with what this machine needs: more ranks than cores, and root in containers.
std::string mpirun(int ranks) {
  std::string line = "mpirun --oversubscribe";
  if (::geteuid() == 0) line += " --allow-run-as-root";
  return line + " -np " + std::to_string(ranks) + " ";
}

// The largest difference of two models' scores that any input can see: per weak classifier the largest
// difference of its responses, summed. The trees must read the same features with the same routing.
double largest_score_difference(const BoostedModel& a, const BoostedModel& b) {
  EXPECT_EQ(a.weak_classifiers().size(), b.weak_classifiers().size());
  double bound = 0.0;
  for (std::size_t k = 0; k < std::min(a.weak_classifiers().size(), b.weak_classifiers().size()); ++k) {
    const WeakClassifier& u = a.weak_classifiers()[k];
    const WeakClassifier& v = b.weak_classifiers()[k];
    EXPECT_EQ(u.feature, v.feature) << "weak classifier " << k;
    EXPECT_EQ(u.nodes.size(), v.nodes.size()) << "weak classifier " << k;
    double largest = 0.0;
    for (std::size_t n = 0; n < std::min(u.nodes.size(), v.nodes.size()); ++n) {
      EXPECT_EQ(u.nodes[n].feature, v.nodes[n].feature) << "weak classifier " << k << " node " << n;
      EXPECT_EQ(u.nodes[n].responses.size(), v.nodes[n].responses.size());
      for (std::size_t j = 0; j < std::min(u.nodes[n].responses.size(), v.nodes[n].responses.size()); ++j) {
        largest = std::max(largest, std::abs(u.nodes[n].responses[j] - v.nodes[n].responses[j]));
      }
    }
    for (std::size_t j = 0; j < std::min(u.responses.size(), v.responses.size()); ++j) {
      largest = std::max(largest, std::abs(u.responses[j] - v.responses[j]));
    }
    bound += largest;
  }
  return bound;
}

class MpiTraining : public ::testing::Test {
 protected:
  void SetUp() override {
    people = dir / "people";
    negatives = dir / "negatives";
    test::make_set(people, 1, 60, 1);
    test::make_set(negatives, 0, 90, 2);
  }
  std::string train(const std::string& launcher, const std::string& models, const std::string& extra) {
    return launcher + test::quote(test::program("rdsf-train")) + " --pos " + test::quote(people) + " --neg " +
           test::quote(negatives) + " --name toy --threads 1 --models-dir " + test::quote(models) + " " + extra;
  }
  // Trains with one process and with `ranks`; returns the largest score difference of the two models.
  // Most runs train on a pool of 256 features: 8,128 would make every round's histograms 32 times larger
  // for these 150 rows.
  double compare(int ranks, const std::string& options, const std::string& tag = "") {
    const std::string one = dir / ("one-" + std::to_string(ranks) + tag), many = dir / ("many-" + std::to_string(ranks) + tag);
    const test::RunResult a = test::run(train("", one, options));
    EXPECT_EQ(a.exit_code, 0) << a.err;
    const test::RunResult b = test::run(train(mpirun(ranks), many, options));
    EXPECT_EQ(b.exit_code, 0) << b.err;
    EXPECT_NE(b.err.find(std::to_string(ranks) + " ranks; rank 0 holds"), std::string::npos) << b.err;
    const BoostedModel m1 = BoostedModel::load(one + "/toy/v1.yml"), mn = BoostedModel::load(many + "/toy/v1.yml");
    EXPECT_EQ(m1.training().validation.source, mn.training().validation.source);
    EXPECT_EQ(m1.training().validation.positives, mn.training().validation.positives);
    EXPECT_EQ(m1.training().validation.negatives, mn.training().validation.negatives);
    EXPECT_NEAR(m1.training().validation.summary.auc, mn.training().validation.summary.auc, 1e-9);
    EXPECT_NEAR(m1.calibration().a, mn.calibration().a, 1e-6);
    EXPECT_NEAR(m1.calibration().b, mn.calibration().b, 1e-6);
    EXPECT_EQ(m1.training().train_positives, mn.training().train_positives);
    const double difference = largest_score_difference(m1, mn);
    std::cout << ranks << " ranks, " << options << ": largest score difference " << difference << "\n";
    // Only the order of the additions differs: the last bits of the responses.
    EXPECT_LT(difference, 1e-9);
    // Nothing beside the one model file (rank 0 wrote it; no partial file).
    EXPECT_EQ(std::distance(fs::directory_iterator(many + "/toy"), fs::directory_iterator{}), 1);
    return difference;
  }
  test::TempDir dir{"rdsf-mpi"};
  std::string people, negatives;
};

TEST_F(MpiTraining, TwoAndThreeRanksTrainTheOneProcessModel) {
  RDSF_REQUIRE_MPIRUN();
  // Defaults: 5 folds by group (here 3 groups), trees of depth 2, mirrored positives, Platt calibration.
  compare(2, "--rounds 12 --feature-pool 256");
  compare(3, "--rounds 12 --feature-pool 256");
}

TEST_F(MpiTraining, HeldOutValidationEarlyStoppingAndTables) {
  RDSF_REQUIRE_MPIRUN();
  compare(3, "--rounds 15 --folds 0 --early-stopping 4 --depth 1 --augment mirror,shift --augment-copies 1 "
             "--feature-pool 256");
}

TEST_F(MpiTraining, SeparateValidationSets) {
  RDSF_REQUIRE_MPIRUN();
  const std::string validation_people = dir / "validation-people", validation_negatives = dir / "validation-negatives";
  test::make_set(validation_people, 1, 20, 5, {}, "other recording");
  test::make_set(validation_negatives, 0, 30, 6, {}, "other recording");
  compare(3, "--rounds 6 --feature-pool 256 --validation-pos " + test::quote(validation_people) +
                 " --validation-neg " + test::quote(validation_negatives), "-separate");
}

TEST_F(MpiTraining, ContinuedTrainingOnEveryFeature) {
  RDSF_REQUIRE_MPIRUN();
  const std::string start = dir / "start";
  const test::RunResult first = test::run(train("", start, "--rounds 3 --depth 1 --folds 0"));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  compare(2, "--rounds 3 --depth 1 --folds 0 --init " + test::quote(start + "/toy/v1.yml"), "-init");
}

// Each rank's exit code, written by a shell around it (OMPI_COMM_WORLD_RANK is mpirun's).
std::string with_exit_codes(const std::string& command, const std::string& codes) {
  return "sh -c " + test::quote(command + "; code=$?; echo \"$OMPI_COMM_WORLD_RANK $code\" >> " + test::quote(codes) +
                                "; exit $code");
}

TEST_F(MpiTraining, ARankThatCannotReadItsShareEndsEveryRank) {
  RDSF_REQUIRE_MPIRUN();
  // The last negative's crop belongs to the last rank's share.
  const SampleSet set = SampleSet::open_read(negatives);
  const std::string last = set.depth_crop_path(set.records().size() - 1);
  ASSERT_FALSE(last.empty());
  std::ofstream(last, std::ios::trunc) << "not a png";
  const std::string models = dir / "models", codes = dir / "codes";
  const test::RunResult r =
      test::run(mpirun(2) + with_exit_codes(train("", models, "--rounds 3 --feature-pool 256"), codes));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("rank 1 of 2: reading its share of the training sets: "), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("rank 0 of 2: reading"), std::string::npos) << r.err;  // rank 0 read its share
  EXPECT_EQ(test::file_text(codes).find(" 0\n"), std::string::npos) << test::file_text(codes);
  EXPECT_NE(test::file_text(codes).find("0 1\n"), std::string::npos) << test::file_text(codes);
  EXPECT_NE(test::file_text(codes).find("1 1\n"), std::string::npos) << test::file_text(codes);
  EXPECT_FALSE(fs::exists(models + "/toy/v1.yml"));
}

TEST_F(MpiTraining, RanksWithOtherOptionsAreRefused) {
  RDSF_REQUIRE_MPIRUN();
  const std::string models = dir / "models";
  std::string line = mpirun(1) + train("", models, "--rounds 3") + " : -np 1 " + train("", models, "--rounds 4");
  const test::RunResult r = test::run(line);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("rank 1 of 2 has other options than rank 0"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rounds 4"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(models + "/toy"));
}

TEST_F(MpiTraining, ARankKilledMidRunLeavesNoModel) {
  RDSF_REQUIRE_MPIRUN();
  const std::string models = dir / "models", pids = dir / "pid", log = dir / "log";
  // Rank 1 notes its process id and becomes rdsf-train; once rank 0 reports rounds, rank 1 is killed.
  const std::string rank = "sh -c " + test::quote("echo $$ > " + test::quote(pids) + ".$OMPI_COMM_WORLD_RANK; exec " +
                                                  train("", models, "--rounds 100000 --depth 1 --feature-pool 256"));
  const std::string script = "(" + mpirun(2) + rank + " 2> " + test::quote(log) + "; echo $? > " +
                             test::quote(dir / "status") + ") & for i in $(seq 600); do grep -q 'round ' " +
                             test::quote(log) + " 2>/dev/null && break; sleep 0.1; done; kill -9 $(cat " +
                             test::quote(pids + ".1") + "); wait";
  const test::RunResult r = test::run("timeout 120 sh -c " + test::quote(script));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::string status = test::file_text(dir / "status");
  EXPECT_NE(status, "0\n") << test::file_text(log);
  EXPECT_FALSE(status.empty());
  EXPECT_FALSE(fs::exists(models + "/toy/v1.yml"));
  // No rdsf-train of this run is left behind.
  EXPECT_NE(test::run("pgrep -f " + test::quote("[r]dsf-train .*" + models)).exit_code, 0);
}

}  // namespace
}  // namespace rdsf
