// The thesis preset reproduces the landed main's candidates exactly on the real frames (boxes, windows,
// layers, crops), and so do today's departures alone (every step added since turned off). The golden
// lines come from main's build (tests/golden/README.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "rdsf/core/stable_hash.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

std::string mat_hash(const cv::Mat& m) {
  if (m.empty()) return "-";
  const cv::Mat c = m.isContinuous() ? m : m.clone();
  return to_hex16(fnv1a64(std::string_view(reinterpret_cast<const char*>(c.data), c.total() * c.elemSize())));
}

std::vector<std::string> candidate_lines(const std::string& folder, const AnalyserParams& params) {
  const FrameAnalyser analyser(params);
  auto source = open_frame_source((test::realdata_dir() / folder).string());
  std::vector<std::string> lines;
  DepthFrame f;
  char line[512];
  while (source->next(f)) {
    const FrameAnalysis a = analyser.analyse(f, false);
    for (std::size_t i = 0; i < a.candidates.size(); ++i) {
      const Candidate& c = a.candidates[i];
      std::snprintf(line, sizeof line, "%s,%zu,%d,%d,%d,%d,%d,%d,%d,%d,%d,%.3f,%.3f,%.3f,%d,%s,%s", f.name.c_str(), i,
                    c.strict_box.x, c.strict_box.y, c.strict_box.width, c.strict_box.height, c.window_unclipped.x,
                    c.window_unclipped.y, c.window_unclipped.width, c.window_unclipped.height, c.layer,
                    c.layer_depth_mm, c.height_cm, c.width_cm, c.highest_column, mat_hash(c.depth_crop).c_str(),
                    mat_hash(c.colour_crop).c_str());
      lines.emplace_back(line);
    }
  }
  return lines;
}

std::vector<std::string> golden(const std::string& name) {
  std::ifstream in(std::filesystem::path(RDSF_SOURCE_DIR) / "tests/golden" / name);
  EXPECT_TRUE(in) << name;
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

void expect_same(const std::vector<std::string>& found, const std::vector<std::string>& expected) {
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t i = 0; i < found.size(); ++i) EXPECT_EQ(found[i], expected[i]) << "candidate line " << i;
}

// thesis_params() with the departures main had switched on.
AnalyserParams todays_departures_only() {
  const AnalyserParams defaults;
  AnalyserParams p = thesis_params();
  p.segmentation.left_border_jump = defaults.segmentation.left_border_jump;
  p.candidates.occlusion_gap_cm = defaults.candidates.occlusion_gap_cm;
  p.candidates.floor_tolerance_mm = defaults.candidates.floor_tolerance_mm;
  return p;
}

}  // namespace

TEST(CandidatesGolden, ThesisPresetReproducesMainsCandidatesWithItsDeparturesOff) {
  RDSF_REQUIRE_REALDATA();
  expect_same(candidate_lines("people", thesis_params()), golden("candidates-thesis-people.csv"));
  expect_same(candidate_lines("empty", thesis_params()), golden("candidates-thesis-empty.csv"));
}

TEST(CandidatesGolden, TodaysDeparturesAloneReproduceMainsDefaults) {
  RDSF_REQUIRE_REALDATA();
  expect_same(candidate_lines("people", todays_departures_only()), golden("candidates-main-people.csv"));
  expect_same(candidate_lines("empty", todays_departures_only()), golden("candidates-main-empty.csv"));
}

TEST(CandidatesGolden, DefaultsDepartFromTheThesis) {
  RDSF_REQUIRE_REALDATA();
  EXPECT_NE(candidate_lines("people", AnalyserParams{}), golden("candidates-main-people.csv"));
}
