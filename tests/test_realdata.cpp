// The frame analyser on the real Kinect frames of ../shared/realdata: recall of the candidates against the
// people in boxes.csv, per frame group, the number of candidates in people-free rooms, and what the shipped
// default model finds there.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/evaluation/detection_metrics.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/pipeline/people_detector.hpp"
#include "support/pipeline_runs.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

std::map<std::string, std::vector<cv::Rect>> read_boxes(const std::filesystem::path& csv) {
  std::map<std::string, std::vector<cv::Rect>> boxes;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header: frame,person,x,y,w,h
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string frame, person, x, y, w, h;
    std::getline(fields, frame, ',');
    std::getline(fields, person, ',');
    std::getline(fields, x, ',');
    std::getline(fields, y, ',');
    std::getline(fields, w, ',');
    std::getline(fields, h, ',');
    boxes[frame].emplace_back(std::stoi(x), std::stoi(y), std::stoi(w), std::stoi(h));
  }
  return boxes;
}

}  // namespace

// The floor: 47 of the folder's 49 people have a candidate whose reported (fitted) box reaches IoU >= 0.5
// (43 with the thesis's strict box; main had 43 of 49 with the strict box, issue 14).
TEST(RealData, CandidatesCoverAtLeast47OfThe49People) {
  RDSF_REQUIRE_REALDATA();
  const auto truth = read_boxes(test::realdata_dir() / "people" / "boxes.csv");
  ASSERT_FALSE(truth.empty());
  const FrameAnalyser analyser;
  auto source = open_frame_source((test::realdata_dir() / "people").string());
  std::map<std::string, std::pair<int, int>> per_group;  // group -> (found, people)
  int found = 0, found_strict = 0, people = 0;
  DepthFrame frame;
  while (source->next(frame)) {
    const FrameAnalysis analysis = analyser.analyse(frame, false);
    const std::string group = frame.name.substr(0, frame.name.find('_'));
    const auto it = truth.find(frame.name);
    if (it == truth.end()) continue;
    for (const cv::Rect& person : it->second) {
      double best = 0, best_strict = 0;
      for (const Candidate& c : analysis.candidates) {
        best = std::max(best, iou(person, reported_box(c, analyser.params().reported_box)));
        best_strict = std::max(best_strict, iou(person, c.strict_box));
      }
      const bool hit = best >= 0.5;
      found += hit;
      found_strict += best_strict >= 0.5;
      ++people;
      per_group[group].first += hit;
      ++per_group[group].second;
      if (!hit) std::cout << "  missed " << frame.name << " (best IoU " << best << ")\n";
    }
  }
  for (const auto& [group, counts] : per_group) {
    std::cout << "  " << group << ": " << counts.first << "/" << counts.second << " people have a candidate\n";
    RecordProperty("recall_" + group, std::to_string(counts.first) + "/" + std::to_string(counts.second));
  }
  std::cout << "  all: " << found << "/" << people << " (fitted box), " << found_strict << " (strict box)\n";
  RecordProperty("recall_strict_box", std::to_string(found_strict) + "/" + std::to_string(people));
  EXPECT_EQ(people, 49);
  EXPECT_GE(found, 47);
  EXPECT_GE(found_strict, 43);
}

TEST(RealData, CandidatesPerFrameInEmptyRooms) {
  RDSF_REQUIRE_REALDATA();
  const FrameAnalyser analyser;
  auto source = open_frame_source((test::realdata_dir() / "empty").string());
  DepthFrame frame;
  int frames = 0;
  std::size_t total = 0;
  while (source->next(frame)) {
    const FrameAnalysis analysis = analyser.analyse(frame);
    std::cout << "  " << frame.name << ": " << analysis.candidates.size() << " candidates, "
              << analysis.segmentation.layers.size() << " layers\n";
    // Every candidate is a valid 64x128 sample with 8128 features.
    for (const Candidate& c : analysis.candidates) {
      EXPECT_EQ(c.depth_crop.size(), cv::Size(64, 128));
      EXPECT_GT(cv::countNonZero(c.depth_crop), 0);
    }
    EXPECT_EQ(analysis.features.cols, 8128);
    total += analysis.candidates.size();
    ++frames;
  }
  std::cout << "  mean: " << static_cast<double>(total) / frames << " candidates per frame\n";
  EXPECT_EQ(frames, 9);
  EXPECT_GT(total, 0u);  // rooms have person-sized things: the classifier's negatives
  EXPECT_LE(total, 49u);  // issue 14: no more than before its departures (5.44 per frame)
}

// The shipped default model (the newest version of 'people', trained on synthetic rooms only) at its operating
// point (P >= 0.27 for people/v3 and v4, which state it; 0.5 for earlier models), with the detection options it
// states (people/v4: --local-front 70), counted as the evaluation counts (detection_figures: highest score
// first, each matched to the person it overlaps most at IoU >= 0.5; the others are false positives).
// people/v4 finds 44 of the 49 with 1 false positive in the 46 frames and 5 detections in the 9 empty rooms;
// people/v3 found 43 with 2 and 5;
// people/v2 (at 0.5) found 43 with 5 and 7 (README, "The default model"); people/v1 found 32.
TEST(RealData, DefaultModelFindsAtLeast40OfThe49PeopleWithFewFalsePositives) {
  RDSF_REQUIRE_REALDATA();
  const std::string path = resolve_model("people", (test::realdata_dir() / "no-models-here").string());
  EXPECT_NE(path.find("people/v4.yml"), std::string::npos) << path;
  // Every detection of a folder's frames, by a fresh detector (its own tracks).
  const auto detections_of = [&](const char* folder) {
    return test::detections_of(path, (test::realdata_dir() / folder).string());
  };
  const double all = -std::numeric_limits<double>::infinity();  // every detection counts
  const DetectionFigures people = detection_figures(
      detections_of("people"), read_ground_truth((test::realdata_dir() / "people" / "boxes.csv").string()), all);
  const DetectionFigures empty = detection_figures(detections_of("empty"), GroundTruth{}, all);
  std::cout << "  " << path << ": " << people.n_det << " of " << people.n_people << " people found, " << people.n_fp
            << " false positives in the people frames, " << empty.n_fp << " detections in the empty rooms\n";
  EXPECT_EQ(people.n_people, 49);
  EXPECT_GE(people.n_det, 40);
  EXPECT_LE(people.n_fp, 5);
  EXPECT_EQ(empty.n_frames, 9);
  EXPECT_LE(empty.n_fp, 7);
}
