// rdsf-perf-report in --quick mode: it writes a Markdown report with every row, each with numbers, prints
// its ratios, and refuses to overwrite a report without --force. No timing assertions: speed is what the
// report measures, not what the test checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/pipeline/stated_options.hpp"
#include "support/test_support.hpp"

namespace {

using namespace rdsf;
using rdsf::test::quote;
using rdsf::test::run;
using rdsf::test::TempDir;

std::string perf_program() {
  return (std::filesystem::path(RDSF_BINARY_DIR) / "bench" / "report" / "rdsf-perf-report").string();
}

/// The table row (a line starting with "| " + label) or an empty string.
std::string row(const std::string& markdown, const std::string& label) {
  std::istringstream lines(markdown);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("| " + label, 0) == 0) return line;
  }
  return {};
}

class PerfReportQuick : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!std::filesystem::exists(perf_program())) return;
    dir_ = new TempDir("rdsf-perf-report-test");
    result_ = new rdsf::test::RunResult(
        run(quote(perf_program()) + " --quick --out " + quote(*dir_ / "report.md") + " --work " +
            quote(*dir_ / "work")));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete dir_;
    result_ = nullptr;
    dir_ = nullptr;
  }
  void SetUp() override {
    if (result_ == nullptr) GTEST_SKIP() << perf_program() << " is not built (RDSF_BUILD_BENCH off)";
  }
  static TempDir* dir_;
  static rdsf::test::RunResult* result_;
};

TempDir* PerfReportQuick::dir_ = nullptr;
rdsf::test::RunResult* PerfReportQuick::result_ = nullptr;

TEST_F(PerfReportQuick, WritesEveryRowWithNumbersAndPrintsTheRatios) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  const std::string md = rdsf::test::file_text(*dir_ / "report.md");
  ASSERT_FALSE(md.empty());
  for (const char* heading : {"# Performance report", "## Whole system per frame and per candidate",
                              "## Training per round", "## Mining and labelling", "## Memory peaks",
                              "## Targets", "**Machine:**", "**Load average**"}) {
    EXPECT_NE(md.find(heading), std::string::npos) << heading;
  }
  // The machine's speed at the start and the end: two positive processor times of the reference loop.
  std::smatch speed;
  ASSERT_TRUE(std::regex_search(md, speed, std::regex(R"(\*\*Machine speed:\*\*[^\n]*took ([0-9.]+) ms of processor time at the start and ([0-9.]+) ms at the end)")))
      << md.substr(0, 1200);
  EXPECT_GT(std::stod(speed[1].str()), 0.0);
  EXPECT_GT(std::stod(speed[2].str()), 0.0);
  std::smatch reads;
  ASSERT_TRUE(std::regex_search(md, reads, std::regex(R"(streaming reads of 256 MiB on one thread ran at ([0-9.]+) and ([0-9.]+) GB/s)")));
  EXPECT_GT(std::stod(reads[1].str()), 0.0);
  EXPECT_GT(std::stod(reads[2].str()), 0.0);
  const std::regex number("[0-9]+(\\.[0-9]+)?");
  const std::vector<std::string> rows = {
      "Segmentation per frame", "Candidate initialisation and filtering per candidate", "RDSF per candidate",
      "Classifier per candidate", "RDSF and classifier per candidate", "Tracking per frame",
      "Whole system, 1 thread", "Whole system, 2 threads (frames in memory)",
      "PNG reading per frame (depth and colour), 1 thread", "Whole system from PNG files, 2 threads",
      "Native Real AdaBoost", "OpenCV cv::ml::Boost REAL stumps", "Ratio (OpenCV / native)",
      "Mining negatives, 2 threads", "Labelling: answer to next candidate, mean",
      "Labelling: answer to next candidate, 95 %", "Labelling: answer to next candidate, max",
      "render and write synthetic frames", "train the pipeline's model", "whole system, 1 thread",
      "whole system, 2 threads", "PNG reading and whole system from files", "training comparison",
      "mining negatives", "labelling session", "Segmentation >= 30x", "Whole system >= 30 fps",
      "Training >= 100x", "Labelling: next candidate within 30 ms"};
  for (const std::string& label : rows) {
    const std::string line = row(md, label);
    ASSERT_FALSE(line.empty()) << "no row '" << label << "' in\n" << md;
    // The cells after the label hold measured numbers.
    const std::string cells = line.substr(line.find('|', 2));
    EXPECT_TRUE(std::regex_search(cells, number)) << line;
    EXPECT_EQ(cells.find("nan"), std::string::npos) << line;
    EXPECT_EQ(cells.find("inf"), std::string::npos) << line;
  }
  // The whole-system rows measured candidates, and the parallel run tracked the same people.
  EXPECT_EQ(md.find("**different from**"), std::string::npos);
  EXPECT_EQ(md.find("0.0 candidates per frame"), std::string::npos);
  // Every target row ends with a verdict.
  for (const char* target : {"Segmentation >= 30x", "Whole system >= 30 fps", "Training >= 100x"}) {
    const std::string line = row(md, target);
    EXPECT_TRUE(line.find("**yes**") != std::string::npos || line.find("**no**") != std::string::npos) << line;
  }
  // The ratios are printed too, and progress goes to stderr.
  EXPECT_NE(result_->out.find("faster than the thesis's 200 ms"), std::string::npos) << result_->out;
  EXPECT_NE(result_->out.find("training per round"), std::string::npos) << result_->out;
  EXPECT_NE(result_->out.find("report: "), std::string::npos) << result_->out;
  EXPECT_NE(result_->err.find("rdsf-perf-report:"), std::string::npos);
}

// What a lab's rdsf-detect without --model costs: the shipped default model with the options it states, beside
// this run's own model (the detector's defaults), on the same frames.
TEST_F(PerfReportQuick, TimesTheShippedDefaultModelWithItsStatedOptions) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  const std::string md = rdsf::test::file_text(*dir_ / "report.md");
  const std::size_t section = md.find("## The shipped default model, as a detector runs it");
  ASSERT_NE(section, std::string::npos) << md;
  const std::string header = row(md.substr(section), "Measure");
  const BoostedModel shipped = BoostedModel::load(resolve_model(kDefaultModelName));
  EXPECT_NE(header.find(model_label(shipped)), std::string::npos) << header;
  const std::string stated = option_words(departures_from_defaults(shipped.detection_options()));
  EXPECT_NE(header.find(stated.empty() ? "no detection option" : stated), std::string::npos) << header;
  const std::regex figure("\\| [0-9]+\\.[0-9]+ (ms|fps)[^|]*\\| [0-9]+\\.[0-9]+ (ms|fps)");
  for (const char* label : {"Segmentation and candidates per frame", "RDSF and classifier per candidate"}) {
    const std::string line = row(md.substr(section), label);
    ASSERT_FALSE(line.empty()) << label;
    EXPECT_TRUE(std::regex_search(line, figure)) << line;  // both models measured
  }
  EXPECT_NE(result_->out.find("the shipped default model " + model_label(shipped)), std::string::npos) << result_->out;
}

// Issue 17: the machine's limits beside the figures, and the trainers side by side (XGBoost measured, or
// said to be absent).
TEST_F(PerfReportQuick, StatesTheMachinesLimitsAndThePeers) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  const std::string md = rdsf::test::file_text(*dir_ / "report.md");
  EXPECT_NE(md.find("## Speed against the machine's limits"), std::string::npos);
  EXPECT_NE(md.find("## Trainers side by side"), std::string::npos);
  const std::regex number("[0-9]+\\.[0-9]+");
  for (const char* label : {"Memory bandwidth, streaming reads", "One pass over a 640x480 frame",
                            "Both PNGs of a frame", "Both PNGs of a frame, libdeflate's inflate alone",
                            "Full 8128 RDSF vector per candidate",
                            "native Real AdaBoost, depth 1", "native Real AdaBoost, depth 3",
                            "native Real AdaBoost, depth 3, histogram subtraction"}) {
    const std::string line = row(md, label);
    ASSERT_FALSE(line.empty()) << "no row '" << label << "' in\n" << md;
    EXPECT_TRUE(std::regex_search(line.substr(line.find('|', 2)), number)) << line;
  }
  for (const char* label : {"XGBoost hist, depth 1", "XGBoost hist, depth 3"}) {
    const std::string line = row(md, label);
    ASSERT_FALSE(line.empty()) << "no row '" << label << "' in\n" << md;
    const bool measured = std::regex_search(line.substr(line.find('|', 2)), number);
    EXPECT_TRUE(measured || line.find("not installed") != std::string::npos) << line;
  }
  EXPECT_NE(md.find("Native round against the machine"), std::string::npos);
}

// These fail before measuring anything, so they do not need the quick run.
TEST(PerfReport, RefusesToReplaceAReportWithoutForce) {
  if (!std::filesystem::exists(perf_program())) GTEST_SKIP() << perf_program() << " is not built";
  TempDir dir("rdsf-perf-report-test");
  std::ofstream(dir / "report.md") << "an earlier report\n";
  const rdsf::test::RunResult again = run(quote(perf_program()) + " --quick --out " + quote(dir / "report.md"));
  EXPECT_EQ(again.exit_code, 1);
  EXPECT_NE(again.err.find("already exists"), std::string::npos) << again.err;
  EXPECT_EQ(rdsf::test::file_text(dir / "report.md"), "an earlier report\n");
}

TEST(PerfReport, RejectsBadOpenCvRounds) {
  if (!std::filesystem::exists(perf_program())) GTEST_SKIP() << perf_program() << " is not built";
  TempDir dir("rdsf-perf-report-test");
  const rdsf::test::RunResult bad =
      run(quote(perf_program()) + " --quick --opencv-rounds 3,1 --out " + quote(dir / "other.md"));
  EXPECT_EQ(bad.exit_code, 2);  // a wrong command line
  EXPECT_NE(bad.err.find("--opencv-rounds"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "other.md"));
}

// A --real-frames folder that is missing or holds no frames is refused at once (not after the run), one line.
TEST(PerfReport, RefusesRealFramesThatAreNoFramesBeforeMeasuring) {
  if (!std::filesystem::exists(perf_program())) GTEST_SKIP() << perf_program() << " is not built";
  TempDir dir("rdsf-perf-report-test");
  std::filesystem::create_directories(std::string(dir / "no-frames"));
  for (const auto& [folder, says] : {std::pair{dir / "missing", "no such folder"},
                                     std::pair{dir / "no-frames", "folder holds no *.depth.png frames"}}) {
    const rdsf::test::RunResult bad =
        run(quote(perf_program()) + " --quick --real-frames " + quote(folder) + " --out " + quote(dir / "r.md"));
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.err.find(std::string(folder) + ": " + says), std::string::npos) << bad.err;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << "measured before refusing: " << bad.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "r.md"));
  }
}

}  // namespace
