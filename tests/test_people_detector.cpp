// rdsf::PeopleDetector on hand-built scenes (boxes, positions and distances worked out by hand), its bad
// input, and the parallel pipeline: 1 thread and N threads give the same results bit for bit.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <limits>

#include "rdsf/classifier/model_file.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/pipeline/people_detector.hpp"
#include "rdsf/pipeline/parallel_pipeline.hpp"
#include "rdsf/synth/synth_sequence.hpp"
#include "support/depth_scenes.hpp"
#include "support/test_support.hpp"

using namespace rdsf;

namespace {

std::string reference_model(const std::string& name = "rdsf-model-v2-tree.yml") {
  return std::string(RDSF_SOURCE_DIR) + "/tests/reference_models/" + name;
}

/// Every candidate is a person (H(x) >= -inf): the reference models are random, so this makes the
/// detections the candidates, which the hand-built scenes fix.
PipelineParams everyone_params() {
  PipelineParams params;
  params.score_threshold = -std::numeric_limits<double>::infinity();
  params.analyser.reported_box = BoxKind::strict;
  return params;
}

/// A wall at 4 m with one person-shaped block at 2 m whose left edge is at column `x`.
DepthFrame person_at(int x, std::int64_t index) {
  DepthFrame frame = test::wall_frame(4000);
  test::paint(frame, {x, 100, 40, 360}, 2000);
  frame.index = index;
  frame.name = "f" + std::to_string(index);
  return frame;
}

/// The detection whose box lies on the block, or null.
const Detection* on_block(const std::vector<Detection>& detections, int x) {
  for (const Detection& d : detections) {
    if (d.box.x <= x + 40 && d.box.x + d.box.width >= x && d.box.y >= 90 && d.box.y <= 110) return &d;
  }
  return nullptr;
}

std::vector<DepthFrame> synthetic_frames(int count) {
  synth::SynthParams p = synth::people_scene(count, 1, 3, 7);
  p.rgb = true;
  p.clip_frames = 8;
  return test::synthetic_frames(p);
}

}  // namespace

TEST(PeopleDetector, HandBuiltPersonHasItsBoxPositionTrackAndDistance) {
  PeopleDetector detector(reference_model(), everyone_params());
  const CameraModel camera;  // Kinect v1: fx = fy = 525, cx = 319.5, cy = 239.5
  const std::vector<Detection> first = detector.detect(person_at(300, 0));
  const Detection* a = on_block(first, 300);
  ASSERT_NE(a, nullptr) << first.size() << " detections";
  // The strict box of a 40 x 360 block: the block's rows, width = height / 2 centred on its top.
  EXPECT_EQ(a->box.y, 100);
  EXPECT_EQ(a->box.height, 360);
  EXPECT_EQ(a->box.width, 180);
  EXPECT_EQ(a->track_id, 1 + (a - first.data()));  // a new track per detection, in order
  // Box centre at the layer depth (2 m), through the pinhole model.
  const double u = a->box.x + a->box.width / 2.0, v = a->box.y + a->box.height / 2.0;
  EXPECT_NEAR(a->position_m.z, 2.0, 1e-9);
  EXPECT_NEAR(a->position_m.x, (u - camera.cx_px) * 2.0 / camera.fx_px, 1e-9);
  EXPECT_NEAR(a->position_m.y, (v - camera.cy_px) * 2.0 / camera.fy_px, 1e-9);
  EXPECT_EQ(a->distance_walked_m, 0.0);
  EXPECT_NEAR(a->probability, detector.model().probability(a->score), 1e-15);

  // 21 px to the right at 2 m: the same track, which has walked 21 * 2 / 525 m.
  const std::vector<Detection> second = detector.detect(person_at(321, 1));
  const Detection* b = on_block(second, 321);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->track_id, a->track_id);
  EXPECT_NEAR(b->position_m.x - a->position_m.x, 21 * 2.0 / 525.0, 1e-9);
  EXPECT_NEAR(b->distance_walked_m, 21 * 2.0 / 525.0, 1e-9);
}

TEST(PeopleDetector, ModelObjectAndPathGiveTheSameDetections) {
  const BoostedModel model = read_model_file(reference_model());
  PeopleDetector from_path(reference_model(), everyone_params());
  PeopleDetector from_model(model, everyone_params());
  for (int k = 0; k < 3; ++k) {
    const DepthFrame frame = person_at(200 + 10 * k, k);
    const std::vector<Detection> x = from_path.detect(frame), y = from_model.detect(frame);
    ASSERT_EQ(x.size(), y.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      EXPECT_EQ(x[i].box, y[i].box);
      EXPECT_EQ(x[i].score, y[i].score);
      EXPECT_EQ(x[i].track_id, y[i].track_id);
      EXPECT_EQ(x[i].distance_walked_m, y[i].distance_walked_m);
    }
  }
}

TEST(PeopleDetector, DefaultThresholdKeepsOnlyCandidatesAtTheModelsProbability) {
  PipelineParams params;
  params.probability_threshold = 0.5;
  PeopleDetector detector(reference_model(), params);
  const DepthFrame frame = person_at(300, 0);
  const PipelineFrame all = detector.pipeline().analyse(frame);
  std::size_t expected = 0;
  for (double p : all.probabilities) expected += p >= 0.5 ? 1 : 0;
  const std::vector<Detection> found = detector.detect(frame);
  EXPECT_EQ(found.size(), expected);
  EXPECT_LT(expected, all.probabilities.size()) << "the threshold should leave some candidates out";
  for (const Detection& d : found) EXPECT_GE(d.probability, 0.5);
}

// Without --threshold (probability_threshold 0) a model is read at the operating point it states; a given
// threshold wins; a model that states none is read at 0.5.
TEST(PeopleDetector, NoThresholdGivenReadsTheModelAtItsOperatingPoint) {
  BoostedModel model = read_model_file(reference_model());
  PipelineParams unset;
  EXPECT_EQ(unset.probability_threshold_for(model), 0.5);
  const DepthFrame frame = person_at(300, 0);
  const PipelineFrame all = PeopleDetector(model, unset).pipeline().analyse(frame);
  ASSERT_FALSE(all.probabilities.empty());
  // An operating point above every candidate's probability: read there, the frame has nobody in it.
  std::vector<double> sorted = all.probabilities;
  std::sort(sorted.begin(), sorted.end());
  const double operating = (sorted.back() + 1.0) / 2;
  model.set_operating_point(OperatingPoint{operating, "test"});
  EXPECT_EQ(unset.probability_threshold_for(model), operating);
  EXPECT_NE(unset.decision_text(model).find(" (its operating point)"), std::string::npos) << unset.decision_text(model);
  EXPECT_EQ(unset.score_threshold_for(model), model.calibration().score_at(operating));
  std::size_t expected = 0;
  for (double p : all.probabilities) expected += p >= operating ? 1 : 0;
  EXPECT_EQ(expected, 0u);
  EXPECT_EQ(PeopleDetector(model, unset).detect(frame).size(), expected);
  PipelineParams given;
  given.probability_threshold = sorted.front() / 2;
  EXPECT_EQ(given.probability_threshold_for(model), sorted.front() / 2);
  EXPECT_EQ(given.decision_text(model).find("operating point"), std::string::npos) << given.decision_text(model);
  given.score_threshold = 0.0;
  EXPECT_EQ(given.probability_threshold_for(model), model.probability(0.0));  // the score threshold's P
  EXPECT_EQ(given.decision_text(model), "people at H(x) >= 0.00, none taller than 250 cm");
  given.max_person_height_cm = 0;  // the limit off (--max-height 0, --thesis): not said
  EXPECT_EQ(given.decision_text(model), "people at H(x) >= 0.00");
  given.max_person_height_cm = 250;
  given.score_threshold.reset();
  EXPECT_GT(PeopleDetector(model, given).detect(frame).size(), expected);
}

TEST(PeopleDetector, BadInputIsOneLineError) {
  // A model file that is not there, and a name that would be looked up: both are refused by path.
  std::string message = test::error_message([] { PeopleDetector d("/nonexistent/model.yml"); });
  EXPECT_NE(message.find("/nonexistent/model.yml"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  message = test::error_message([] { PeopleDetector d("people"); });
  EXPECT_FALSE(message.empty());

  // A model of another feature spec than the detector's: named both, adopting the model's spec works.
  PipelineParams rect;
  rect.analyser.features = FeatureSpec::rect();
  message = test::error_message([&] { PeopleDetector d(reference_model(), rect); });
  EXPECT_NE(message.find("rdsf-rect/1"), std::string::npos) << message;
  EXPECT_NE(message.find("rdsf-model-v2-tree.yml"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  const BoostedModel model = read_model_file(reference_model());
  EXPECT_NO_THROW(PeopleDetector(model, PeopleDetector::params_for(model, rect)));

  // A frame of another size than its camera model, and one without depth.
  PeopleDetector detector(reference_model());
  DepthFrame small;
  small.depth_mm = cv::Mat1w(240, 320, std::uint16_t{2000});
  small.name = "small";
  message = test::error_message([&] { detector.detect(small); });
  EXPECT_NE(message.find("frame small: 320x240 depth image, but its camera model is 640x480"), std::string::npos)
      << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  small.camera = small.camera.scaled_to(320, 240);
  EXPECT_NO_THROW(detector.detect(small));
  DepthFrame empty;
  empty.name = "empty";
  message = test::error_message([&] { detector.detect(empty); });
  EXPECT_NE(message.find("frame empty: has no depth image"), std::string::npos) << message;
}

TEST(ParallelPipeline, OneAndManyThreadsGiveIdenticalResults) {
  const std::vector<DepthFrame> frames = synthetic_frames(24);
  const BoostedModel model = read_model_file(reference_model());
  PipelineParams params = PipelineParams{};
  params.score_threshold = model.calibration().score_at(0.3);  // some detections, some not

  // The reference: PeoplePipeline::process frame after frame.
  PeoplePipeline sequential(params, &model);
  std::vector<PipelineFrame> reference;
  for (const DepthFrame& f : frames) reference.push_back(sequential.process(f));
  std::size_t detections = 0;
  for (const PipelineFrame& r : reference) {
    for (int id : r.person) detections += id != 0 ? 1 : 0;
  }
  ASSERT_GT(detections, 0u);

  for (int threads : {1, 2, 3, 5}) {
    for (std::size_t ahead : {std::size_t{0}, std::size_t{1}, std::size_t{3}}) {
      PeoplePipeline pipeline(params, &model);
      std::vector<PipelineFrame> got;
      const std::int64_t n = run_in_frame_order(
          pipeline, static_cast<std::int64_t>(frames.size()),
          [&](std::int64_t i) { return frames[static_cast<std::size_t>(i)]; }, {threads, ahead},
          [&](const DepthFrame& f, PipelineFrame& r) {
            EXPECT_EQ(f.index, static_cast<std::int64_t>(got.size()));  // in frame order
            got.push_back(r);
            return true;
          });
      ASSERT_EQ(n, static_cast<std::int64_t>(frames.size()));
      for (std::size_t i = 0; i < frames.size(); ++i) {
        const PipelineFrame& a = reference[i];
        const PipelineFrame& b = got[i];
        ASSERT_EQ(a.analysis.candidates.size(), b.analysis.candidates.size()) << "frame " << i << " threads " << threads;
        for (std::size_t c = 0; c < a.analysis.candidates.size(); ++c) {
          EXPECT_EQ(a.analysis.candidates[c].fitted_box, b.analysis.candidates[c].fitted_box);
          EXPECT_EQ(a.analysis.candidates[c].layer_depth_mm, b.analysis.candidates[c].layer_depth_mm);
        }
        EXPECT_EQ(a.scores, b.scores) << "frame " << i << " threads " << threads;  // bit for bit
        EXPECT_EQ(a.probabilities, b.probabilities);
        EXPECT_EQ(a.person, b.person) << "frame " << i << " threads " << threads;
      }
      ASSERT_EQ(pipeline.tracker().people().size(), sequential.tracker().people().size());
      for (std::size_t p = 0; p < pipeline.tracker().people().size(); ++p) {
        EXPECT_EQ(pipeline.tracker().people()[p].distance_cm, sequential.tracker().people()[p].distance_cm);
      }
    }
  }
}

// The pipeline cuts colour crops for its detections only (colour_crops_of_all off, the default): the same
// scores, colour histograms and people as cutting every candidate's, the detections' colour crops the same
// pixels, the other candidates' left empty.
TEST(PeoplePipeline, ColourCropsOfDetectionsOnlyChangeNothingButTheOthersCrops) {
  const std::vector<DepthFrame> frames = synthetic_frames(24);
  const BoostedModel model = read_model_file(reference_model());
  PipelineParams params = PipelineParams{};
  params.score_threshold = model.calibration().score_at(0.3);  // some detections, some not
  PipelineParams all_params = params;
  all_params.colour_crops_of_all = true;
  PeoplePipeline lazy(params, &model), all(all_params, &model);
  std::size_t detections = 0, others = 0;
  for (const DepthFrame& f : frames) {
    const PipelineFrame a = all.process(f), b = lazy.process(f);
    ASSERT_EQ(a.analysis.candidates.size(), b.analysis.candidates.size());
    EXPECT_EQ(a.scores, b.scores) << f.name;
    EXPECT_EQ(a.person, b.person) << f.name;
    for (std::size_t c = 0; c < a.analysis.candidates.size(); ++c) {
      const Candidate& x = a.analysis.candidates[c];
      const Candidate& y = b.analysis.candidates[c];
      EXPECT_EQ(a.histograms[c].values, b.histograms[c].values) << f.name << " candidate " << c;
      EXPECT_EQ(cv::norm(x.depth_crop, y.depth_crop, cv::NORM_INF), 0.0);
      ASSERT_FALSE(x.colour_crop.empty());
      if (b.person[c] != 0) {
        ++detections;
        ASSERT_EQ(x.colour_crop.size(), y.colour_crop.size()) << f.name << " candidate " << c;
        EXPECT_EQ(cv::norm(x.colour_crop, y.colour_crop, cv::NORM_INF), 0.0) << f.name << " candidate " << c;
      } else {
        ++others;
        EXPECT_TRUE(y.colour_crop.empty()) << f.name << " candidate " << c;
      }
    }
  }
  EXPECT_GT(detections, 0u);
  EXPECT_GT(others, 0u);
}

TEST(ParallelPipeline, FolderDecodedOnWorkersEqualsTheSourceAndStopsWhenAsked) {
  const test::TempDir dir("rdsf-parallel-folder");
  const std::string folder = dir / "frames";
  test::write_two_person_frames(folder);
  const BoostedModel model = read_model_file(reference_model());
  PeoplePipeline sequential(everyone_params(), &model);
  std::vector<std::vector<int>> reference;
  auto source = open_frame_source(folder);
  DepthFrame frame;
  std::vector<std::string> names;
  while (source->next(frame)) {
    reference.push_back(sequential.process(frame).person);
    names.push_back(frame.name);
  }
  for (int threads : {1, 2}) {
    PeoplePipeline pipeline(everyone_params(), &model);
    auto files = open_frame_source(folder);
    std::vector<std::vector<int>> got;
    std::vector<std::string> got_names;
    run_in_frame_order(pipeline, *files, CameraModel{}, {threads, 0}, [&](const DepthFrame& f, PipelineFrame& r) {
      got.push_back(r.person);
      got_names.push_back(f.name);
      return true;
    });
    EXPECT_EQ(got, reference);
    EXPECT_EQ(got_names, names);
    // on_frame returning false stops after that frame.
    PeoplePipeline stopped(everyone_params(), &model);
    auto again = open_frame_source(folder);
    EXPECT_EQ(run_in_frame_order(stopped, *again, CameraModel{}, {threads, 0},
                                 [](const DepthFrame&, PipelineFrame&) { return false; }),
              1);
  }
}

TEST(PeopleDetector, DetectionsOfParallelRunsEqualDetect) {
  const std::vector<DepthFrame> frames = synthetic_frames(10);
  PeopleDetector one(reference_model(), everyone_params());
  PeopleDetector many(reference_model(), everyone_params());
  std::vector<std::vector<Detection>> parallel;
  run_in_frame_order(
      many.pipeline(), static_cast<std::int64_t>(frames.size()),
      [&](std::int64_t i) { return frames[static_cast<std::size_t>(i)]; }, {2, 0},
      [&](const DepthFrame& f, PipelineFrame& r) {
        parallel.push_back(many.detections(f, r));
        return true;
      });
  ASSERT_EQ(parallel.size(), frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const std::vector<Detection> d = one.detect(frames[i]);
    ASSERT_EQ(d.size(), parallel[i].size());
    for (std::size_t k = 0; k < d.size(); ++k) {
      EXPECT_EQ(d[k].box, parallel[i][k].box);
      EXPECT_EQ(d[k].track_id, parallel[i][k].track_id);
      EXPECT_EQ(d[k].position_m, parallel[i][k].position_m);
      EXPECT_EQ(d[k].distance_walked_m, parallel[i][k].distance_walked_m);
    }
  }
}
