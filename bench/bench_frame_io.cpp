// Speed of reading a frame from PNG files on one core (issue 17: at least 3x faster than cv::imdecode):
// a synthetic 640x480 frame with 2..4 people written as the 16-bit depth PNG and the 8-bit colour PNG
// that rdsf-synth writes (cv::imencode), then read back with the direct path (rdsf::read_png_file) and
// with cv::imdecode alone (PngDecodeOptions::direct_path = false: what every read did before). Both
// include reading the file and checking every chunk's CRC. Arg 0 = depth, 1 = colour, 2 = both.
// Run: build/bench/bench_frame_io
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "rdsf/frame/depth_png.hpp"
#include "rdsf/frame/png_decoder.hpp"
#include "rdsf/synth/synth_sequence.hpp"

namespace {

struct PngPair {
  std::filesystem::path dir;
  std::string depth, colour;
  ~PngPair() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

const PngPair& files() {
  static const PngPair pair = [] {
    rdsf::synth::SynthParams p;
    p.frames = 1;
    p.people_min = 2;
    p.people_max = 4;
    p.seed = 11;
    p.rgb = true;
    rdsf::synth::SynthSequence sequence(p);
    const rdsf::synth::SynthFrame frame = sequence.frame(0);
    const auto dir = std::filesystem::temp_directory_path() / ("rdsf-bench-frame-io-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    rdsf::write_png_atomically((dir / "0.depth.png").string(), frame.depth_mm);
    rdsf::write_png_atomically((dir / "0.rgb.png").string(), frame.bgr);
    return PngPair{dir, (dir / "0.depth.png").string(), (dir / "0.rgb.png").string()};  // no copy (C++17)
  }();
  return pair;
}

void read_frame(benchmark::State& state, bool direct) {
  const rdsf::PngDecodeOptions options{direct};
  const PngPair& pair = files();
  for (auto _ : state) {
    if (state.range(0) != 1) benchmark::DoNotOptimize(rdsf::read_png_file(pair.depth, options).data);
    if (state.range(0) != 0) benchmark::DoNotOptimize(rdsf::read_png_file(pair.colour, options).data);
  }
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_ReadPngDirect(benchmark::State& state) { read_frame(state, true); }
void BM_ReadPngImdecode(benchmark::State& state) { read_frame(state, false); }
BENCHMARK(BM_ReadPngDirect)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadPngImdecode)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
