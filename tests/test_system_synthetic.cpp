// The whole workbench through its programs on synthetic data, as a user would run it: render, label in
// assisted mode, mine negatives, train, then detect, track and evaluate on a held-out sequence.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "support/test_support.hpp"

using namespace rdsf;

namespace {

std::string tool(const std::string& name) { return test::quote(test::program(name)); }

void must_run(const std::string& command) {
  const test::RunResult r = test::run(command);
  ASSERT_EQ(r.exit_code, 0) << command << "\n" << r.err;
}

}  // namespace

// On the plainer generator (--classic): the figures below were measured on it; the default variety of
// rdsf-synth (docs/synthetic.md) is harder and is measured by the main job.
TEST(SystemSynthetic, TrainedModelDetectsAndTracksHeldOutPeople) {
  test::TempDir dir;
  const std::string d = dir.path().string();
  const std::string synth = tool("rdsf-synth") + " --classic --out " + d;
  must_run(synth + "/train --frames 600 --people 1..3 --seed 5 --clip-frames 10 --rgb");
  must_run(synth + "/empty --frames 300 --people 1..3 --seed 5 --clip-frames 10 --empty");
  must_run(synth + "/test --frames 150 --people 1..2 --seed 6 --clip-frames 50 --rgb");
  must_run(tool("rdsf-label") + " --source " + d + "/train --out " + d + "/people --truth " + d +
           "/train/boxes.csv --answers /dev/null");
  must_run(tool("rdsf-mine") + " --source " + d + "/empty --out " + d + "/negatives");
  must_run(tool("rdsf-train") + " --name system --models-dir " + d + "/models --pos " + d + "/people --neg " + d +
           "/negatives --rounds 100 --folds 4");
  const test::RunResult r = test::run(tool("rdsf-detect") + " --source " + d + "/test --truth " + d +
                                      "/test/boxes.csv --model system --models-dir " + d + "/models --report-dir " +
                                      d + "/report --thresholds=0.01:0.99:0.01 --clip-frames 50 --out " + d + "/detections.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::cout << r.out;
  for (const char* file : {"metrics.csv", "clips.csv", "outcomes.csv", "summary.txt", "summary.md", "roc.png", "det.png"}) {
    EXPECT_TRUE(std::filesystem::exists(d + "/report/" + file)) << file;
  }
  // summary.md's row ends with the 95 % intervals of TAR at FPPF <= 0.1 and 0.5 over the people, then over
  // the 3 clips (150 frames rendered in clips of 50; fewer than 10 clips are flagged "few").
  {
    std::ifstream md(d + "/report/summary.md");
    std::string header, rule, row;
    std::getline(md, header);
    std::getline(md, rule);
    std::getline(md, row);
    EXPECT_NE(header.find("| TAR at FPPF <= 0.1 / 0.5: 95 % interval over the people | ... over clips (clips) |"),
              std::string::npos)
        << header;
    EXPECT_TRUE(std::regex_search(
        row, std::regex(R"(\| [01]\.\d\d-[01]\.\d\d / [01]\.\d\d-[01]\.\d\d \| [01]\.\d\d-[01]\.\d\d / [01]\.\d\d-[01]\.\d\d \(3, few\) \|$)")))
        << row;
  }
  // The report's clips.csv joins the set's (rdsf-synth's) in scripts/clip-conditions.py: 3 clips, the
  // people of the report's row, read by condition.
  {
    const test::RunResult conditions = test::run("/usr/bin/python3 " + test::quote(std::string(RDSF_SOURCE_DIR) +
                                                 "/scripts/clip-conditions.py") + " " + d + "/test:" + d + "/report");
    ASSERT_EQ(conditions.exit_code, 0) << conditions.err;
    EXPECT_NE(conditions.out.find("3 clips of 1 sets, 100 people"), std::string::npos) << conditions.out;
    EXPECT_NE(conditions.out.find("| camera | clips (with people) | people | candidate recall |"), std::string::npos) << conditions.out;
    const test::RunResult wrong = test::run("/usr/bin/python3 " + test::quote(std::string(RDSF_SOURCE_DIR) +
                                            "/scripts/clip-conditions.py") + " " + d + "/test:" + d + "/nothing");
    EXPECT_EQ(wrong.exit_code, 1);
    EXPECT_NE(wrong.err.find(d + "/nothing/clips.csv"), std::string::npos) << wrong.err;
  }
  // scripts/paired-clips.py redoes the exact curve from outcomes.csv: the report against itself reads the
  // summary's TAR at FPPF <= 0.1 on both sides and a difference of 0.
  {
    const test::RunResult paired = test::run("/usr/bin/python3 " + test::quote(std::string(RDSF_SOURCE_DIR) +
                                             "/scripts/paired-clips.py") + " " + d + "/report:" + d + "/report");
    ASSERT_EQ(paired.exit_code, 0) << paired.err;
    std::ifstream md(d + "/report/summary.md");
    std::string line;
    std::getline(md, line);
    std::getline(md, line);
    std::getline(md, line);
    std::smatch tar;
    ASSERT_TRUE(std::regex_search(line, tar, std::regex(R"(^\| [^|]+ \| ([01]\.\d{3}) \|)"))) << line;
    EXPECT_NE(paired.out.find("| TAR at FPPF <= 0.1 | " + tar[1].str() + " | " + tar[1].str() + " | +0.000 (+0.000 to +0.000) |"),
              std::string::npos)
        << paired.out;
  }
  // Best MOTA over the sweep, from metrics.csv (column 15, table "all").
  std::ifstream metrics(d + "/report/metrics.csv");
  std::string line;
  std::getline(metrics, line);
  double best_mota = -1e9, tar_at_zero = 0;
  while (std::getline(metrics, line)) {
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
    ASSERT_EQ(f.size(), 21u) << line;
    if (f[1] != "all") continue;
    best_mota = std::max(best_mota, std::stod(f[15]));
    if (std::abs(std::stod(f[2]) - 0.5) < 1e-9) tar_at_zero = std::stod(f[9]);
  }
  std::cout.precision(6);
  std::cout << "best MOTA " << best_mota << ", TAR at P >= 0.5 " << tar_at_zero << "\n";
  // Measured here (deterministic: same seeds, same bytes, same model): best MOTA 0.800 at threshold 7,
  // TAR 0.84 at FPPF <= 0.1. The issue asks for MOTA >= 0.8 at the best threshold.
  EXPECT_GE(best_mota, 0.8);
  EXPECT_GE(tar_at_zero, 0.5);
}
