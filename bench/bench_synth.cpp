// Speed of the synthetic Kinect generator at 640x480 on one core: rendering (scene, z-buffer, sensor
// model, ground truth), with colour, and the PNG encoding of a depth frame (what writing adds).
#include <benchmark/benchmark.h>

#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "bench/bench_scene.hpp"
#include "rdsf/synth/synth_sequence.hpp"

namespace {

rdsf::synth::SynthParams bench_params(bool rgb) { return rdsf::bench::bench_scene(100000, rgb); }

void BM_SynthRenderDepth(benchmark::State& state) {
  rdsf::synth::SynthSequence sequence(bench_params(false));
  int index = 0;
  for (auto _ : state) {
    rdsf::synth::SynthFrame frame = sequence.frame(index++);
    benchmark::DoNotOptimize(frame.depth_mm.data);
  }
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(index), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SynthRenderDepth)->Unit(benchmark::kMillisecond);

void BM_SynthRenderDepthAndColour(benchmark::State& state) {
  rdsf::synth::SynthSequence sequence(bench_params(true));
  int index = 0;
  for (auto _ : state) {
    rdsf::synth::SynthFrame frame = sequence.frame(index++);
    benchmark::DoNotOptimize(frame.bgr.data);
  }
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(index), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SynthRenderDepthAndColour)->Unit(benchmark::kMillisecond);

void BM_SynthEncodeDepthPng(benchmark::State& state) {
  rdsf::synth::SynthSequence sequence(bench_params(false));
  const rdsf::synth::SynthFrame frame = sequence.frame(0);
  std::vector<unsigned char> bytes;
  for (auto _ : state) {
    cv::imencode(".png", frame.depth_mm, bytes);
    benchmark::DoNotOptimize(bytes.data());
  }
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SynthEncodeDepthPng)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
