// Speed of the frame analyser's stages on one core, on the real frames of ../shared/realdata when present
// (else a hand-built scene). Targets (issue 2): segmentation < 10 ms per 640x480 frame (thesis 200-320 ms),
// candidate shaping < 1 ms per candidate (thesis 10 ms), RDSF < 100 us per candidate (thesis ~16 ms with the
// classifier). Issue 17: a 100-round model scored from only the features it reads < 5 us per candidate
// (BM_ScoreModelFeaturesOnly/rdsf), the full 8128 vector < 20 us (BM_RdsfPerCandidate); issue 13: the
// rdsf-rect spec scored at most at the old full-vector cost, about 64 us (BM_ScoreModelFeaturesOnly/rect).
// BM_CandidateShapingSynthetic and BM_SegmentationSynthetic run on the performance report's 48 synthetic frames;
// BM_AnalyseWithBackground times segmentation and candidates with and without a background model (issue 34).
// Run: build/bench/bench_core
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <utility>
#include <vector>

#include <random>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/pipeline/mirror_scoring.hpp"
#include "rdsf/pipeline/model_scorer.hpp"
#include "rdsf/pipeline/people_pipeline.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/segmentation/background_model.hpp"
#include "rdsf/segmentation/depth_layers.hpp"
#include "rdsf/synth/synth_sequence.hpp"

namespace {

const std::vector<rdsf::DepthFrame>& frames() {
  static const std::vector<rdsf::DepthFrame> loaded = [] {
    std::vector<rdsf::DepthFrame> all;
    const std::filesystem::path real = std::filesystem::path(RDSF_SOURCE_DIR).parent_path() / "shared/realdata";
    for (const char* group : {"people", "empty"}) {
      if (!std::filesystem::is_directory(real / group)) continue;
      auto source = rdsf::open_frame_source((real / group).string());
      rdsf::DepthFrame frame;
      while (source->next(frame)) all.push_back(frame);
    }
    if (all.empty()) {  // no real frames here: a person before a wall
      rdsf::DepthFrame frame;
      frame.depth_mm = cv::Mat1w(480, 640, std::uint16_t{4000});
      frame.depth_mm(cv::Rect(300, 100, 40, 360)).setTo(2000);
      all.push_back(frame);
    }
    return all;
  }();
  return loaded;
}

void segment_frames(benchmark::State& state, const std::vector<rdsf::DepthFrame>& frames) {
  const rdsf::SegmentationParams params;
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(rdsf::segment_depth(frames[i++ % frames.size()].depth_mm, params));
}

void BM_Segmentation(benchmark::State& state) { segment_frames(state, frames()); }
BENCHMARK(BM_Segmentation)->Unit(benchmark::kMillisecond);

// find_candidates over `frames` in turn, with candidates per frame and time per candidate.
void shape_candidates(benchmark::State& state, const std::vector<rdsf::DepthFrame>& frames) {
  std::vector<rdsf::Segmentation> segmentations;
  for (const auto& frame : frames) segmentations.push_back(rdsf::segment_depth(frame.depth_mm, {}));
  const rdsf::CandidateParams params;
  std::size_t i = 0;
  std::int64_t candidates = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % frames.size();
    const auto found = rdsf::find_candidates(frames[k], segmentations[k], params);
    candidates += static_cast<std::int64_t>(found.size());
    benchmark::DoNotOptimize(found.data());
  }
  state.counters["candidates_per_frame"] =
      static_cast<double>(candidates) / static_cast<double>(state.iterations());
  // Seconds per candidate (shown with an SI prefix: 150u = 150 microseconds).
  state.counters["time_per_candidate"] = benchmark::Counter(
      static_cast<double>(candidates), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_CandidateShaping(benchmark::State& state) { shape_candidates(state, frames()); }
BENCHMARK(BM_CandidateShaping)->Unit(benchmark::kMillisecond);

// The performance report's synthetic frames (48, 1..4 people, seed 17), with their registered colour.
const std::vector<rdsf::DepthFrame>& synthetic_frames() {
  static const std::vector<rdsf::DepthFrame> made = [] {
    rdsf::synth::SynthParams p = rdsf::synth::people_scene(48, 1, 4, 17);
    p.rgb = true;
    rdsf::synth::SynthSequence sequence(p);
    std::vector<rdsf::DepthFrame> all;
    for (int i = 0; i < p.frames; ++i) all.push_back(sequence.frame(i).depth_frame(p.camera()));
    return all;
  }();
  return made;
}

// Candidates per candidate on the synthetic frames: 0 depth only (as the report's "speed against the
// machine's limits"), 1 with colour crops (as the whole system cuts them).
void BM_CandidateShapingSynthetic(benchmark::State& state) {
  std::vector<rdsf::DepthFrame> frames = synthetic_frames();
  if (state.range(0) == 0) {
    for (rdsf::DepthFrame& f : frames) f.bgr.release();
  }
  shape_candidates(state, frames);
}
BENCHMARK(BM_CandidateShapingSynthetic)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_SegmentationSynthetic(benchmark::State& state) { segment_frames(state, synthetic_frames()); }
BENCHMARK(BM_SegmentationSynthetic)->Unit(benchmark::kMillisecond);

// Segmentation and candidates per frame with a background model of the room (issue 34: rdsf-detect
// --background) against without, on one static synthetic room with people against its walls (48 frames,
// seed 41's first clip of `rdsf-synth --moving-camera 0 --wall-clearance 0.25 --people 1..4`), the
// background learned from the same room rendered empty. 0: without, 1: with, 2: without it but with the
// frame's own local background (--local-front 70, the shipped people/v4's option).
void BM_AnalyseWithBackground(benchmark::State& state) {
  static const auto scene = [] {
    rdsf::synth::SynthParams p = rdsf::synth::people_scene(48, 1, 4, 41);
    p.clip_frames = 48;
    p.room.moving_share = 0.0, p.people.clearance_m = 0.25;
    std::pair<std::vector<rdsf::DepthFrame>, std::shared_ptr<const rdsf::BackgroundModel>> made;
    rdsf::synth::SynthSequence people(p);
    for (int i = 0; i < p.frames; ++i) made.first.push_back(people.frame(i).depth_frame(p.camera()));
    p.empty = true;
    rdsf::synth::SynthSequence room(p);
    rdsf::BackgroundLearner learner;
    for (int i = 0; i < p.frames; ++i) learner.add(room.frame(i).depth_frame(p.camera()));
    made.second = std::make_shared<const rdsf::BackgroundModel>(learner.model());
    return made;
  }();
  rdsf::AnalyserParams params;
  if (state.range(0) == 1) params.background = scene.second;
  if (state.range(0) == 2) params.local_front_reach_cm = 70.0;
  const rdsf::FrameAnalyser analyser(params);
  std::size_t i = 0;
  std::int64_t candidates = 0;
  for (auto _ : state) {
    const auto a = analyser.analyse(scene.first[i++ % scene.first.size()], false, rdsf::CropColour::later);
    candidates += static_cast<std::int64_t>(a.candidates.size());
    benchmark::DoNotOptimize(a.candidates.data());
  }
  state.counters["candidates_per_frame"] = static_cast<double>(candidates) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_AnalyseWithBackground)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

const std::vector<cv::Mat1w>& crops() {
  static const std::vector<cv::Mat1w> all = [] {
    std::vector<cv::Mat1w> out;
    const rdsf::FrameAnalyser analyser;
    for (const auto& frame : frames()) {
      for (const auto& c : analyser.analyse(frame, false).candidates) out.push_back(c.depth_crop);
    }
    return out;
  }();
  return all;
}

// Argument 0: the thesis's spec (rdsf, 8128 features), 1: the paper's squares (rdsf-rect, 120,786).
rdsf::FeatureSpec spec_of(const benchmark::State& state) {
  return state.range(0) == 0 ? rdsf::FeatureSpec{} : rdsf::FeatureSpec::rect();
}

// A 100-round model of look-up tables on seeded random features: as many distinct regions as 100 pairs
// can name (a trained model reuses cells, so it reads fewer).
rdsf::BoostedModel random_model(const rdsf::FeatureSpec& spec, int rounds) {
  std::mt19937 random(17);
  std::vector<rdsf::WeakClassifier> weak(static_cast<std::size_t>(rounds));
  for (rdsf::WeakClassifier& w : weak) {
    w.feature = static_cast<int>(random() % static_cast<unsigned>(spec.dimension()));
    for (int b = 0; b < 64; ++b) w.responses.push_back(static_cast<double>(random() % 1000) / 500.0 - 1.0);
  }
  return rdsf::BoostedModel(spec, rdsf::BinScheme{}, weak);
}

void per_candidate(benchmark::State& state) {
  state.counters["time_per_candidate"] = benchmark::Counter(
      static_cast<double>(state.iterations()), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_RdsfPerCandidate(benchmark::State& state) {
  const rdsf::RdsfExtractor extractor(spec_of(state));
  std::vector<float> out(static_cast<std::size_t>(extractor.dimension()));
  std::size_t i = 0;
  for (auto _ : state) {
    extractor.compute(crops()[i++ % crops().size()], out.data());
    benchmark::DoNotOptimize(out.data());
  }
  per_candidate(state);
}
BENCHMARK(BM_RdsfPerCandidate)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// The full vector, then H(x): the thesis's way of scoring.
void BM_ScoreFullVector(benchmark::State& state) {
  const rdsf::RdsfExtractor extractor(spec_of(state));
  const rdsf::BoostedModel model = random_model(extractor.spec(), 100);
  std::vector<float> out(static_cast<std::size_t>(extractor.dimension()));
  std::size_t i = 0;
  for (auto _ : state) {
    extractor.compute(crops()[i++ % crops().size()], out.data());
    benchmark::DoNotOptimize(model.score(out.data()));
  }
  per_candidate(state);
}
BENCHMARK(BM_ScoreFullVector)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// Only the features the 100-round model reads (the regions they name, then the pairs), then H(x). With
// RDSF_BENCH_MODEL=FILE (a trained model, e.g. of scripts/feature-spec-compare.sh) argument 2 scores with it.
void BM_ScoreModelFeaturesOnly(benchmark::State& state) {
  const char* trained = std::getenv("RDSF_BENCH_MODEL");
  if (state.range(0) == 2 && trained == nullptr) {
    state.SkipWithError("set RDSF_BENCH_MODEL=FILE to score with a trained model");
    return;
  }
  const rdsf::ModelScorer scorer(state.range(0) == 2 ? rdsf::BoostedModel::load(trained)
                                                     : random_model(spec_of(state), 100));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(scorer.score(crops()[i++ % crops().size()]));
  per_candidate(state);
  state.counters["features"] = scorer.features().size();
  state.counters["regions"] = scorer.features().region_count();
}
BENCHMARK(BM_ScoreModelFeaturesOnly)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

// Mirror averaging (PipelineParams::mirror_average, the default): argument 0 scores a crop, 1 scores the
// crop and its mirror as the pipeline does (ModelScorer::compute_with_mirror: the mirror's features from
// the crop's regions, one pass), 2 the same by flipping the crop and computing its features again (the way
// before 2026-12-07; the same bits): the price per candidate.
void BM_ScoreWithMirror(benchmark::State& state) {
  const rdsf::ModelScorer scorer(random_model(rdsf::FeatureSpec{}, 100));
  std::vector<float> crop_values(static_cast<std::size_t>(scorer.features().size())), mirror_values(crop_values.size());
  cv::Mat1w flipped;
  std::size_t i = 0;
  for (auto _ : state) {
    const cv::Mat1w& crop = crops()[i++ % crops().size()];
    double h = 0.0;
    if (state.range(0) == 0) {
      h = scorer.score(crop);
    } else if (state.range(0) == 1) {
      scorer.compute_with_mirror(crop, crop_values.data(), mirror_values.data());
      h = 0.5 * (scorer.score_features(crop_values.data()) + scorer.score_features(mirror_values.data()));
    } else {
      cv::flip(crop, flipped, 1);
      h = 0.5 * (scorer.score(crop) + scorer.score(flipped));
    }
    benchmark::DoNotOptimize(h);
  }
  per_candidate(state);
  state.counters["mirrors_by_regions"] = scorer.mirrors_by_regions() ? 1 : 0;
}
BENCHMARK(BM_ScoreWithMirror)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

// A model adapted to a room (100 inherited rounds and 3 of its own): argument 0 scores its crop alone (as
// before 2026-12-07), 1 as the pipeline does by default, its inherited rounds mirror-averaged
// (PipelineParams::mirror_average_inherited, pipeline/mirror_scoring.hpp): the price per candidate.
void BM_ScoreAdaptedModel(benchmark::State& state) {
  rdsf::BoostedModel adapted = random_model(rdsf::FeatureSpec{}, 103);
  adapted.training().parameters.emplace_back("init_weak_classifiers", "100");
  adapted.training().parameters.emplace_back("adapted_room", "bench");
  rdsf::PipelineParams params;
  params.mirror_average_inherited = state.range(0) == 1;
  const rdsf::ModelScorer scorer(adapted);
  const rdsf::MirrorScoring mirror(adapted, params);
  std::vector<rdsf::Candidate> one(1);
  cv::Mat1f crop_features, mirror_features;
  std::size_t i = 0;
  for (auto _ : state) {
    one[0].depth_crop = crops()[i++ % crops().size()];
    scorer.compute(one, crop_features, mirror.reads_mirror() ? &mirror_features : nullptr);
    std::vector<double> score = scorer.score_rows(crop_features);
    mirror.apply(scorer, one, crop_features, mirror_features, score);
    benchmark::DoNotOptimize(score[0]);
  }
  per_candidate(state);
}
BENCHMARK(BM_ScoreAdaptedModel)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_WholeCoreFrame(benchmark::State& state) {
  const rdsf::FrameAnalyser analyser;
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(analyser.analyse(frames()[i++ % frames().size()], true));
}
BENCHMARK(BM_WholeCoreFrame)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
