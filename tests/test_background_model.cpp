// The background model of the room (segmentation/background_model.hpp) and the candidates it adds
// (candidates/foreground_candidates.hpp): learning, the foreground rule at its margin, a person against a
// wall, a free-standing person unchanged, thread counts, bad input and the stored folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>

#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/frame/depth_png.hpp"
#include "rdsf/frame/png_folder_source.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"
#include "rdsf/segmentation/background_model.hpp"
#include "support/depth_scenes.hpp"
#include "support/pipeline_runs.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

// The room: a wall at 3 m behind the whole image.
constexpr int kWallMm = 3000;
// A person 25 cm in front of it: a head (24 px) on a body (60 px), 330 rows tall (1.73 m at 2.75 m).
constexpr int kPersonMm = 2750;
const cv::Rect kPerson(300, 100, 60, 330);

void paint_person(DepthFrame& frame, const cv::Rect& body, int depth_mm) {
  test::paint(frame, {body.x + body.width / 2 - 12, body.y, 24, 40}, depth_mm);  // head
  test::paint(frame, {body.x, body.y + 40, body.width, body.height - 40}, depth_mm);
}

DepthFrame person_frame(const cv::Rect& body, int depth_mm) {
  DepthFrame frame = test::wall_frame(kWallMm);
  paint_person(frame, body, depth_mm);
  return frame;
}

std::shared_ptr<const BackgroundModel> wall_background() {
  BackgroundLearner learner;
  for (int i = 0; i < 5; ++i) learner.add(test::wall_frame(kWallMm));
  return std::make_shared<const BackgroundModel>(learner.model());
}

const Candidate* best_match(const std::vector<Candidate>& candidates, const cv::Rect& truth, double* overlap) {
  const Candidate* best = nullptr;
  *overlap = 0;
  for (const Candidate& c : candidates) {
    if (iou(c.fitted_box, truth) > *overlap) *overlap = iou(c.fitted_box, truth), best = &c;
  }
  return best;
}

}  // namespace

TEST(BackgroundModel, LearnsTheRoomWhereAPersonPassesInAMinorityOfFrames) {
  std::vector<DepthFrame> frames;
  for (int i = 0; i < 10; ++i) {
    DepthFrame f = test::wall_frame(kWallMm);
    if (i == 3 || i == 4) test::paint(f, {100, 100, 50, 200}, 1500);  // someone passing: 2 of 10 frames
    if (i % 2 == 0) f.depth_mm(50, 400) = 0;                          // a flickering reading: half the frames
    f.depth_mm(60, 400) = 0;                                           // never read
    f.depth_mm(70, 400) = static_cast<std::uint16_t>(2000 + 10 * i);   // readings 2000, 2010, ... 2090
    frames.push_back(f);
  }
  BackgroundLearner forward, backward;
  for (const DepthFrame& f : frames) forward.add(f);
  for (auto f = frames.rbegin(); f != frames.rend(); ++f) backward.add(*f);
  const BackgroundModel model = forward.model();
  EXPECT_EQ(model.far_mm(150, 120), kWallMm);  // the room behind the person who passed
  EXPECT_EQ(model.far_mm(50, 400), kWallMm);   // missing readings are left out, not counted as far
  EXPECT_EQ(model.far_mm(60, 400), 0);         // never seen
  EXPECT_EQ(model.far_mm(70, 400), 2070);      // rank floor(0.8 * 9) = 7 of the sorted readings
  EXPECT_EQ(model.camera, frames.front().camera);
  EXPECT_EQ(cv::countNonZero(model.far_mm != backward.model().far_mm), 0);  // whatever the frames' order

  BackgroundLearner median(0.5);
  for (const DepthFrame& f : frames) median.add(f);
  EXPECT_EQ(median.model().far_mm(70, 400), 2040);  // rank floor(0.5 * 9) = 4
}

TEST(BackgroundModel, ForegroundRuleAtTheMargin) {
  // In front when d < b - max(margin_mm, margin_relative * b): 100 mm at 1 m, 3 % = 150 mm at 5 m.
  cv::Mat1w background(1, 8), depth(1, 8);
  const std::uint16_t b[] = {1000, 1000, 5000, 5000, 0, 0, 1000, 2000};
  const std::uint16_t d[] = {899, 900, 4849, 4850, 7000, 0, 0, 2500};
  for (int i = 0; i < 8; ++i) background(0, i) = b[i], depth(0, i) = d[i];
  const cv::Mat1b front = foreground_mask(depth, background, BackgroundParams{});
  const std::uint8_t expected[] = {255, 0, 255, 0, 255, 0, 0, 0};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(front(0, i), expected[i]) << "pixel " << i;
  const cv::Mat1b wide = foreground_mask(depth, background, BackgroundParams{200.0, 0.0});
  EXPECT_EQ(wide(0, 0), 0);  // 101 mm nearer is not enough for a 200 mm margin
  EXPECT_EQ(wide(0, 2), 0);
}

TEST(BackgroundModel, PersonAgainstAWallIsACandidateOnlyWithTheBackground) {
  const DepthFrame frame = person_frame(kPerson, kPersonMm);
  double without_overlap = 0, with_overlap = 0;
  const FrameAnalysis off = FrameAnalyser().analyse(frame, false);
  best_match(off.candidates, kPerson, &without_overlap);
  EXPECT_LT(without_overlap, 0.5);  // one layer with the wall: no candidate of the person alone

  AnalyserParams params;
  params.background = wall_background();
  const FrameAnalysis on = FrameAnalyser(params).analyse(frame, false);
  const Candidate* person = best_match(on.candidates, kPerson, &with_overlap);
  ASSERT_NE(person, nullptr);
  EXPECT_GE(with_overlap, 0.5);  // the fitted box: at least 0.3 of the height wide (a narrow person here)
  EXPECT_TRUE(person->foreground);
  EXPECT_EQ(person->strict_box.y, kPerson.y);  // head to feet, not the waist
  EXPECT_EQ(person->strict_box.height, kPerson.height);
  EXPECT_NEAR(person->layer_depth_mm, kPersonMm, 1.0);  // the foreground's own depth, not the wall's
  double lowest = 65535, highest = 0;
  cv::minMaxLoc(person->depth_crop, nullptr, &highest);
  cv::minMaxLoc(person->depth_crop, &lowest, nullptr, nullptr, nullptr, person->depth_crop > 0);
  EXPECT_EQ(highest, kPersonMm);  // the crop holds the person's pixels only, no wall
  EXPECT_EQ(lowest, kPersonMm);
  // The layers' own candidates come first and are kept (added beside them, never replacing them).
  ASSERT_GE(on.candidates.size(), off.candidates.size());
  for (std::size_t i = 0; i < off.candidates.size(); ++i) {
    EXPECT_EQ(on.candidates[i].strict_box, off.candidates[i].strict_box);
    EXPECT_FALSE(on.candidates[i].foreground);
  }
  EXPECT_EQ(cv::countNonZero(on.in_front.labels), kPerson.height * kPerson.width - 40 * (kPerson.width - 24));
}

TEST(BackgroundModel, ColourCropsCutLaterUseTheForegroundLabels) {
  DepthFrame frame = person_frame(kPerson, kPersonMm);
  frame.bgr = cv::Mat3b(frame.depth_mm.size(), cv::Vec3b(200, 100, 50));
  AnalyserParams params;
  params.background = wall_background();
  const FrameAnalysis a = FrameAnalyser(params).analyse(frame, false, CropColour::cut);
  const auto person = std::find_if(a.candidates.begin(), a.candidates.end(), [](const Candidate& c) { return c.foreground; });
  ASSERT_NE(person, a.candidates.end());
  const cv::Mat3b cut = person->colour_crop.clone();
  Candidate later = *person;
  later.colour_crop = cv::Mat3b();  // a buffer of its own (a copied Candidate shares its crops' pixels)
  cut_colour_crop(frame, a.in_front.labels, later);  // what PeoplePipeline does for a foreground detection
  EXPECT_EQ(cv::norm(later.colour_crop, cut, cv::NORM_L1), 0.0);
  EXPECT_EQ(cv::sum(cut)[0], 200.0 * cv::countNonZero(person->depth_crop));  // only the person's pixels
  later.colour_crop = cv::Mat3b();
  cut_colour_crop(frame, a.segmentation.labels, later);  // the layer's labels would colour the wall too
  EXPECT_GT(cv::sum(later.colour_crop)[0], cv::sum(cut)[0]);
}

TEST(BackgroundModel, AFreeStandingPersonKeepsItsCandidateAndGetsNoDuplicate) {
  const cv::Rect body(300, 40, 90, 420);  // 1.60 m tall at 2 m
  const DepthFrame frame = person_frame(body, 2000);  // 1 m in front of the wall: a layer of its own
  const FrameAnalysis off = FrameAnalyser().analyse(frame, false);
  AnalyserParams params;
  params.background = wall_background();
  const FrameAnalysis on = FrameAnalyser(params).analyse(frame, false);
  double overlap = 0;
  ASSERT_NE(best_match(off.candidates, body, &overlap), nullptr);
  EXPECT_GE(overlap, 0.5);
  ASSERT_EQ(on.candidates.size(), off.candidates.size());  // the same person in front: dropped as a duplicate
  for (std::size_t i = 0; i < off.candidates.size(); ++i) EXPECT_EQ(on.candidates[i].fitted_box, off.candidates[i].fitted_box);
}

TEST(BackgroundModel, ResultsDoNotDependOnTheThreadCount) {
  std::vector<DepthFrame> frames;
  for (int i = 0; i < 8; ++i) {
    DepthFrame f = person_frame({40 + 60 * i, 100, 60, 330}, i % 2 == 0 ? kPersonMm : 1800);
    f.index = i;
    f.name = std::to_string(i);
    frames.push_back(f);
  }
  PipelineParams params;
  params.analyser.background = wall_background();
  const test::CandidateBoxes one = test::candidate_boxes(params, frames, 1);
  ASSERT_EQ(one.size(), frames.size());
  const std::size_t added = test::foreground_count(one);
  EXPECT_GE(added, 4u);  // the people against the wall
  EXPECT_EQ(test::candidate_boxes(params, frames, 2), one);
}

TEST(BackgroundModel, AFrameOfAnotherSizeOrCameraIsAOneLineError) {
  auto background = std::make_shared<BackgroundModel>(*wall_background());
  background->path = "room/bg";
  AnalyserParams params;
  params.background = background;
  DepthFrame small;
  small.depth_mm = cv::Mat1w(240, 320, static_cast<std::uint16_t>(kWallMm));
  small.camera = CameraModel::kinect_v1().scaled_to(320, 240);
  small.name = "f7";
  EXPECT_EQ(test::error_message([&] { FrameAnalyser(params).analyse(small, false); }),
            "background room/bg: learned from 640x480 frames, but frame f7 is 320x240");
  DepthFrame other = test::wall_frame(kWallMm);
  other.camera.fx_px = 580;
  other.name = "f8";
  EXPECT_EQ(test::error_message([&] { FrameAnalyser(params).analyse(other, false); }),
            "background room/bg: learned with camera 640x480 fx=525 fy=525 cx=319.5 cy=239.5, but frame f8 has "
            "640x480 fx=580 fy=525 cx=319.5 cy=239.5");
  BackgroundLearner learner;
  learner.add(test::wall_frame(kWallMm));
  EXPECT_NE(test::error_message([&] { learner.add(small); }).find("frame f7: 320x240"), std::string::npos);
}

TEST(BackgroundModel, TheStoredFolderReadsBackAndIsAFrameSource) {
  test::TempDir dir("rdsf-background");
  BackgroundLearner learner;
  learner.add(person_frame(kPerson, 1500));
  learner.add(test::wall_frame(kWallMm));
  BackgroundModel model = learner.model();
  model.far_mm(0, 0) = 0;  // never seen survives the round trip
  const std::string folder = dir / "bg";
  write_background(folder, model, false);
  const BackgroundModel back = read_background(folder);
  EXPECT_EQ(cv::countNonZero(back.far_mm != model.far_mm), 0);
  EXPECT_EQ(back.camera, model.camera);
  EXPECT_EQ(back.path, folder);
  EXPECT_EQ(test::error_message([&] { write_background(folder, model, false); }),
            folder + "/background.depth.png: already exists");
  EXPECT_EQ(test::error_message([&] { write_background(folder, model, true); }), "");
  PngFolderSource source(folder, CameraModel::kinect_v1());  // rdsf-detect --source DIR shows it
  DepthFrame frame;
  ASSERT_TRUE(source.next(frame));
  EXPECT_EQ(frame.name, "background");
  EXPECT_EQ(cv::countNonZero(frame.depth_mm != model.far_mm), 0);
  EXPECT_FALSE(source.next(frame));
  EXPECT_NE(test::error_message([&] { read_background(dir / "missing"); }).find("camera.yml: missing"), std::string::npos);
}

TEST(BackgroundModel, EvenlySpacedFrames) {
  EXPECT_EQ(evenly_spaced(10, 3), (std::vector<std::int64_t>{0, 5, 9}));  // round(i * 9 / 2): 4.5 rounds up
  EXPECT_EQ(evenly_spaced(3, 5), (std::vector<std::int64_t>{0, 1, 2}));
  EXPECT_EQ(evenly_spaced(7, 1), (std::vector<std::int64_t>{0}));
  EXPECT_TRUE(evenly_spaced(0, 4).empty());
}

TEST(BackgroundModel, ProgramsLearnAndUseIt) {
  test::TempDir dir("rdsf-background-program");
  const DepthFrame wall = test::wall_frame(kWallMm);
  std::filesystem::create_directories(dir / "room");
  for (int i = 0; i < 3; ++i) write_png_atomically(dir / ("room/" + std::to_string(i) + ".depth.png"), wall.depth_mm);
  const std::string learn = test::program("rdsf-background") + " --source " + test::quote(dir / "room") + " --out " +
                            test::quote(dir / "bg");
  const test::RunResult learned = test::run(learn);
  ASSERT_EQ(learned.exit_code, 0) << learned.err;
  EXPECT_NE(learned.err.find("learned from 3 frames"), std::string::npos) << learned.err;
  EXPECT_EQ(test::run(learn).exit_code, 1);  // not replaced without --force

  std::filesystem::create_directories(dir / "people");
  write_png_atomically(dir / "people/p.depth.png", person_frame(kPerson, kPersonMm).depth_mm);
  const std::string detect = test::program("rdsf-detect") + " --candidates-only";
  const std::string people = " --source " + test::quote(dir / "people");
  const test::RunResult off = test::run(detect + people + " --out " + test::quote(dir / "off.csv"));
  const test::RunResult on = test::run(detect + people + " --out " + test::quote(dir / "on.csv") + " --background " +
                                       test::quote(dir / "bg"));
  ASSERT_EQ(off.exit_code, 0) << off.err;
  ASSERT_EQ(on.exit_code, 0) << on.err;
  const auto lines = [](const std::string& path) {
    std::ifstream in(path);
    return std::count(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>(), '\n');
  };
  EXPECT_EQ(lines(dir / "on.csv"), lines(dir / "off.csv") + 1);  // the person against the wall

  cv::Mat1w small(240, 320, static_cast<std::uint16_t>(kWallMm));
  std::filesystem::create_directories(dir / "small");
  write_png_atomically(dir / "small/s.depth.png", small);
  const test::RunResult wrong = test::run(detect + " --out " + test::quote(dir / "s.csv") + " --background " +
                                          test::quote(dir / "bg") + " --source " + test::quote(dir / "small"));
  EXPECT_EQ(wrong.exit_code, 1);
  const std::string line = "rdsf-detect: error: background " + dir / "bg" +
                           ": learned from 640x480 frames, but frame s is 320x240\n";
  EXPECT_NE(wrong.err.find(line), std::string::npos) << wrong.err;
}
