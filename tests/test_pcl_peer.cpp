// rdsf-pcl-people, the quality report's peer (PCL's ground-based people detector), on the real frames of
// ../shared/realdata that have colour. Skips when PCL was not found at configure time (the program is then
// not built) or when the real frames are absent.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "rdsf/analysis/detection_csv.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using rdsf::test::quote;

std::string peer_program() {
  return (fs::path(RDSF_BINARY_DIR) / "peers" / "pcl_people" / "rdsf-pcl-people").string();
}

#define SKIP_WITHOUT_PEER()                                                                          \
  if (!fs::exists(peer_program())) GTEST_SKIP() << "rdsf-pcl-people not built (PCL not found: apt-get install libpcl-dev)"; \
  RDSF_REQUIRE_REALDATA()

/// A list file of the real people frames whose names start with `prefix` (with colour when `colour`).
std::string list_of(const rdsf::test::TempDir& dir, const std::string& prefix, bool colour) {
  const fs::path people = rdsf::test::realdata_dir() / "people";
  const std::string list = dir / (prefix + (colour ? "colour" : "all") + ".txt");
  std::ofstream out(list);
  for (const auto& entry : fs::directory_iterator(people)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0 || name.size() < 10 || name.substr(name.size() - 10) != ".depth.png") continue;
    const std::string stem = name.substr(0, name.size() - 10);
    if (colour != fs::exists(people / (stem + ".rgb.png"))) continue;
    out << fs::absolute(entry.path()).string() << "\n";
  }
  return list;
}

TEST(PclPeer, FindsPeopleInTheHomeFramesAndWritesTheDetectorsCsvAndReport) {
  SKIP_WITHOUT_PEER();
  rdsf::test::TempDir dir("pcl-peer");
  const std::string truth = (rdsf::test::realdata_dir() / "people" / "boxes.csv").string();
  const auto r = rdsf::test::run(quote(peer_program()) + " --source " + quote(list_of(dir, "home_", true)) +
                                 " --out " + quote(dir / "pcl.csv") + " --truth " + quote(truth) +
                                 " --report-dir " + quote(dir / "report"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = rdsf::test::file_text(dir / "pcl.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), rdsf::DetectionCsv::header(true));
  // PCL's app with its defaults: each of the 4 home frames with colour shows one person; the floor is found
  // and at least two of them are detected (above -1.5) with a box the evaluation matches.
  EXPECT_NE(r.err.find("recording 'home_' (4 frames): floor"), std::string::npos) << r.err;
  const std::string summary = rdsf::test::file_text(dir / "report/summary.md");
  EXPECT_NE(summary.find("| PCL ground-based HOG+SVM |"), std::string::npos) << summary;
  EXPECT_NE(r.out.find("4 frames, 4 people"), std::string::npos) << r.out;
  const std::string operating = "At the operating point P >= 0.05: TAR ";
  const std::size_t found = r.out.find(operating);
  ASSERT_NE(found, std::string::npos) << r.out;
  EXPECT_GE(std::stod(r.out.substr(found + operating.size(), 5)), 0.5) << r.out;
}

TEST(PclPeer, AFrameWithoutColourIsAOneLineError) {
  SKIP_WITHOUT_PEER();
  rdsf::test::TempDir dir("pcl-peer-grey");
  const auto r = rdsf::test::run(quote(peer_program()) + " --source " + quote(list_of(dir, "lab_height", false)) +
                                 " --out " + quote(dir / "pcl.csv"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("has no colour image"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "pcl.csv"));
}

TEST(PclPeer, BadOptionsAreUsageErrors) {
  SKIP_WITHOUT_PEER();
  const auto r = rdsf::test::run(quote(peer_program()) + " --source x --out y --voxel-size 2");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--voxel-size"), std::string::npos) << r.err;
}

}  // namespace
