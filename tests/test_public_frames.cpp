// Public real frames: datasets/public/<SOURCE>/ in this repository, one folder per public source
// (datasets/public/README.md; docs/quality.md, "Public real frames"), converted by scripts/public-frames.py.
// Each folder holds NAME.depth.png frames in millimetres, a README.md that records the source repository
// and commit and names the licence and whether people are in the frames, the licence text (LICENSE*), and
// boxes.csv where people are labelled.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <regex>
#include <vector>

#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/evaluation/detection_metrics.hpp"
#include "rdsf/evaluation/ground_truth.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/pipeline/people_detector.hpp"
#include "support/pipeline_runs.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

const std::filesystem::path kPublicFrames = std::filesystem::path(RDSF_SOURCE_DIR) / "datasets" / "public";

std::vector<std::filesystem::path> source_folders() {
  std::vector<std::filesystem::path> folders;
  for (const auto& entry : std::filesystem::directory_iterator(kPublicFrames))
    if (entry.is_directory()) folders.push_back(entry.path());
  std::sort(folders.begin(), folders.end());
  return folders;
}

// The README's "- People: ..." line says "none" for folders of people-free rooms.
bool people_free(const std::filesystem::path& folder) {
  return std::regex_search(test::file_text(folder / "README.md"), std::regex(R"(\n- People: none\b)"));
}

}  // namespace

TEST(PublicFrames, EveryFolderRecordsItsSourceCommitAndLicence) {
  const auto folders = source_folders();
  ASSERT_FALSE(folders.empty()) << kPublicFrames << " has no source folder";
  // The licences a public frame may carry here: they allow redistribution.
  const std::regex licence(R"(\n- Licence: (CC BY 4\.0|CC0|BSD-[23]-Clause|MIT|Apache-2\.0|public domain)\b)");
  const std::regex commit(R"(@ [0-9a-f]{40}\b)");
  for (const auto& folder : folders) {
    SCOPED_TRACE(folder.string());
    ASSERT_TRUE(std::filesystem::is_regular_file(folder / "README.md"));
    const std::string readme = test::file_text(folder / "README.md");
    EXPECT_TRUE(std::regex_search(readme, licence)) << "README.md names no redistributable licence";
    EXPECT_TRUE(std::regex_search(readme, commit)) << "README.md records no source commit";
    EXPECT_TRUE(std::regex_search(readme, std::regex(R"(\n- People: )"))) << "README.md does not say whether people are in the frames";
    bool licence_file = false;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      licence_file |= entry.path().filename().string().rfind("LICENSE", 0) == 0 && entry.file_size() > 0;
    EXPECT_TRUE(licence_file) << "no LICENSE file beside the frames";
  }
}

// Every frame reads as millimetres: at least a quarter of the pixels with a reading (tue_hero's high hall,
// whose far end and shiny floor give none, has a third; the rooms 0.5 or more), a median reading between 0.3
// and 10 m (a frame left in TUM's 5000-per-metre units would have a median beyond 10 m for a room 2 m deep).
TEST(PublicFrames, FramesReadAsMillimetreDepth) {
  int frames = 0;
  for (const auto& folder : source_folders()) {
    auto source = open_frame_source(folder.string());
    DepthFrame frame;
    int in_folder = 0;
    while (source->next(frame)) {
      SCOPED_TRACE(folder.filename().string() + "/" + frame.name);
      ++in_folder;
      ASSERT_EQ(frame.depth_mm.type(), CV_16UC1);
      EXPECT_EQ(frame.width_px(), frame.camera.width_px);
      EXPECT_EQ(frame.height_px(), frame.camera.height_px);
      std::vector<std::uint16_t> valid;
      for (int y = 0; y < frame.depth_mm.rows; ++y)
        for (int x = 0; x < frame.depth_mm.cols; ++x)
          if (frame.depth_mm(y, x) > 0) valid.push_back(frame.depth_mm(y, x));
      ASSERT_GE(valid.size(), frame.depth_mm.total() / 4) << "fewer than a quarter of the pixels have a reading";
      std::nth_element(valid.begin(), valid.begin() + valid.size() / 2, valid.end());
      const std::uint16_t median_mm = valid[valid.size() / 2];
      EXPECT_GE(median_mm, 300);
      EXPECT_LE(median_mm, 10000);
    }
    EXPECT_GT(in_folder, 0) << folder << " has no NAME.depth.png frame";
    frames += in_folder;
  }
  std::cout << "  " << frames << " public frames read\n";
}

// The shipped default model in the people-free public rooms, at its operating point: measured 0 detections
// in 7 frames (people/v3 at P >= 0.27; people/v2 at 0.5 with mirror averaging too; v2 with the crop alone
// 2: a desk front between two office chairs, a desk and wall block). The bound leaves room for a better model only; a worse one fails.
TEST(PublicFrames, DefaultModelInPeopleFreeRoomsMakesAtMostTwoDetectionsInSevenFrames) {
  const std::string path = resolve_model("people", (kPublicFrames / "no-models-here").string());
  int frames = 0, detections = 0;
  for (const auto& folder : source_folders()) {
    if (!people_free(folder)) continue;
    PeopleDetector detector(path);
    auto source = open_frame_source(folder.string());
    DepthFrame frame;
    int in_folder = 0;
    while (source->next(frame)) {
      ++frames;
      in_folder += static_cast<int>(detector.detect(frame).size());
    }
    std::cout << "  " << folder.filename().string() << ": " << in_folder << " detections\n";
    detections += in_folder;
  }
  std::cout << "  " << path << ": " << detections << " detections in " << frames << " people-free public frames\n";
  ASSERT_GT(frames, 0) << "no folder's README says '- People: none'";
  EXPECT_LE(detections * 7, 2 * frames) << "more than 2 detections per 7 people-free frames";
}

// The people of the labelled public frame (PCL's five_people: five people walking away down a corridor at
// 1.8-2.8 m, three cut by the image's bottom edge): the default model at its operating point finds all 5
// (counted as the evaluation counts, IoU >= 0.5 with the hand-drawn boxes) and nothing else (people/v3 at
// P >= 0.27; people/v2 at 0.5 found 4, the fifth scoring just under, P 0.45-0.5). No model chose anything
// on this frame: it is the third real source, unseen.
TEST(PublicFrames, DefaultModelFindsTheFivePeopleInTheCorridor) {
  const std::filesystem::path folder = kPublicFrames / "pcl_people";
  const GroundTruth truth = read_ground_truth((folder / "boxes.csv").string());
  ASSERT_EQ(truth.people(), 5u);
  const double all = -std::numeric_limits<double>::infinity();  // every detection counts
  const DetectionFigures found = detection_figures(
      test::detections_of(resolve_model("people", (kPublicFrames / "no-models-here").string()), folder.string()),
      truth, all);
  std::cout << "  " << found.n_det << " of " << found.n_people << " people found, " << found.n_fp
            << " other detections\n";
  EXPECT_EQ(found.n_det, 5);
  EXPECT_EQ(found.n_fp, 0);
}

// tue_hero: a Toyota HSR robot's head camera in a RoboCup venue hall (five frames of ROS 1 bags, an Xtion-class
// sensor, camera.yml from its CameraInfo): one man standing 1.7-2.0 m away in every frame, counted, and three
// people seated in a row by the left border, mostly hidden, "don't care" (visible < 0.5: rdsf-detect's
// default). Measured: people/v4 at its operating point finds the man in all 5 frames and nothing else that
// counts (its other detections, in three frames, are on the seated people at 4.9 m behind a chair); so did
// people/v3, v2 and v1; PCL's peer found none of the 5 (docs/quality.md, "Public real frames"). No model or
// option was chosen on these frames: the fourth real source, unseen.
TEST(PublicFrames, DefaultModelFindsTheStandingManInTheHall) {
  const std::filesystem::path folder = kPublicFrames / "tue_hero";
  GroundTruth truth = read_ground_truth((folder / "boxes.csv").string());
  EXPECT_EQ(ignore_hardly_visible(truth, 0.5), 15u);
  ASSERT_EQ(truth.people(), 20u);
  const double all = -std::numeric_limits<double>::infinity();  // every detection counts
  const std::vector<FrameCandidates> detections =
      test::detections_of(resolve_model("people", (kPublicFrames / "no-models-here").string()), folder.string());
  ASSERT_EQ(detections.size(), 5u);
  const DetectionFigures found = detection_figures(detections, truth, all);
  std::cout << "  " << found.n_det << " of " << found.n_people << " counted people found, " << found.n_fp
            << " other detections\n";
  EXPECT_EQ(found.n_people, 5);
  EXPECT_EQ(found.n_det, 5);
  EXPECT_EQ(found.n_fp, 0);
}
