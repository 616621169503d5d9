// Speed of reading a frame from PNG files on one core (issue 17: at least 3x faster than cv::imdecode):
// a synthetic 640x480 frame with 2..4 people written as the 16-bit depth PNG and the 8-bit colour PNG
// that rdsf-synth writes (cv::imencode), then read back with the direct path (rdsf::read_png_file) and
// with cv::imdecode alone (PngDecodeOptions::direct_path = false: what every read did before). Both
// include reading the file and checking every chunk's CRC. Arg 0 = depth, 1 = colour, 2 = both.
// BM_InflateOnly is the floor under the direct path: libdeflate's inflate of the same zlib streams alone.
// BM_ReadFolderSource (issue 36): the PNG folder source's frames per second from files on 1 and 2 threads.
// BM_EncodeCrop (issue 17): one sample crop, depth (64x128, 16-bit) and colour (8-bit BGR), to PNG bytes, per
// crop: the candidates' crops of ../shared/realdata/empty (with colour; else of the synthetic frame above), in turn.
// Args {0, 0}: cv::imencode level 1; {1, 0}: the direct zlib path (the same bytes); {2, L}: libdeflate at
// level L. Counters: depth_bytes and colour_bytes, the mean PNG size of a crop.
// Run: build/bench/bench_frame_io
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <libdeflate.h>
#include <unistd.h>

#include <opencv2/imgcodecs.hpp>

#include "bench/bench_scene.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/frame/depth_png.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/frame/png_decoder.hpp"
#include "rdsf/frame/png_encoder.hpp"
#include "rdsf/frame/png_folder_source.hpp"
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
    rdsf::synth::SynthSequence sequence(rdsf::bench::bench_scene(1, /*rgb=*/true));
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

/// The zlib stream of a PNG file: its IDAT chunks' data joined.
std::vector<unsigned char> idat_stream(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return rdsf::png_zlib_stream(path, bytes.data(), bytes.size());
}

/// The floor of the direct path: libdeflate's inflate of the files' zlib streams alone (in memory, no CRC
/// walk, no unfiltering), the part no PNG reader built on libdeflate can avoid.
void BM_InflateOnly(benchmark::State& state) {
  const PngPair& pair = files();
  std::vector<std::vector<unsigned char>> streams;
  if (state.range(0) != 1) streams.push_back(idat_stream(pair.depth));
  if (state.range(0) != 0) streams.push_back(idat_stream(pair.colour));
  std::vector<unsigned char> out(640 * 480 * 3 + 480 + 64);
  libdeflate_decompressor* inflater = libdeflate_alloc_decompressor();
  for (auto _ : state) {
    for (const auto& stream : streams) {
      std::size_t got = 0;
      if (libdeflate_zlib_decompress(inflater, stream.data(), stream.size(), out.data(), out.size(), &got) !=
          LIBDEFLATE_SUCCESS) {
        state.SkipWithError("inflate failed");
      }
      benchmark::DoNotOptimize(out.data());
    }
  }
  libdeflate_free_decompressor(inflater);
}
BENCHMARK(BM_InflateOnly)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// The PNG folder frame source reading ../shared/realdata/people (else the synthetic frame above) from its
// files, on 1 and 2 threads (issue 36): each thread reads every other frame with read_frame, as the
// programs' workers do; frames_per_s is over the wall time, the page cache warm after the first pass.
void BM_ReadFolderSource(benchmark::State& state) {
  const auto people = std::filesystem::path(RDSF_SOURCE_DIR).parent_path() / "shared/realdata/people";
  static const rdsf::PngFolderSource source(
      std::filesystem::is_directory(people) ? people.string() : files().dir.string(), rdsf::CameraModel::kinect_v1());
  const std::size_t frames = source.depth_paths().size();
  std::size_t i = static_cast<std::size_t>(state.thread_index());
  for (auto _ : state) {
    benchmark::DoNotOptimize(source.read_frame(i % frames).depth_mm.data);
    i += static_cast<std::size_t>(state.threads());
  }
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ReadFolderSource)->Threads(1)->Threads(2)->UseRealTime()->Unit(benchmark::kMillisecond);

struct CropPair {
  cv::Mat1w depth;
  cv::Mat3b colour;
};

const std::vector<CropPair>& sample_crops() {
  static const std::vector<CropPair> all = [] {
    const auto empty = std::filesystem::path(RDSF_SOURCE_DIR).parent_path() / "shared/realdata/empty";
    auto source = rdsf::open_frame_source(std::filesystem::is_directory(empty) ? empty.string() : files().dir.string());
    std::vector<CropPair> out;
    const rdsf::FrameAnalyser analyser;
    rdsf::DepthFrame frame;
    while (source->next(frame)) {
      for (const auto& c : analyser.analyse(frame, false).candidates) out.push_back({c.depth_crop.clone(), c.colour_crop.clone()});
    }
    return out;
  }();
  return all;
}

void BM_EncodeCrop(benchmark::State& state) {
  const std::vector<CropPair>& crops = sample_crops();
  if (crops.empty()) {
    state.SkipWithError("no crops");
    return;
  }
  const int mode = static_cast<int>(state.range(0));
  rdsf::PngEncodeOptions options{1};
  if (mode == 2) {
    options.deflater = rdsf::PngDeflater::libdeflate;
    options.libdeflate_level = static_cast<int>(state.range(1));
  }
  const auto encode = [&](const cv::Mat& image) {
    if (mode != 0) return rdsf::encode_png(image, options);
    std::vector<unsigned char> bytes;
    cv::imencode(".png", image, bytes, {cv::IMWRITE_PNG_COMPRESSION, 1});
    return bytes;
  };
  double depth_bytes = 0, colour_bytes = 0;
  for (const CropPair& c : crops) {
    depth_bytes += static_cast<double>(encode(c.depth).size());
    if (!c.colour.empty()) colour_bytes += static_cast<double>(encode(c.colour).size());
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const CropPair& c = crops[i++ % crops.size()];
    benchmark::DoNotOptimize(encode(c.depth).data());
    if (!c.colour.empty()) benchmark::DoNotOptimize(encode(c.colour).data());
  }
  state.counters["depth_bytes"] = depth_bytes / static_cast<double>(crops.size());
  state.counters["colour_bytes"] = colour_bytes / static_cast<double>(crops.size());
  state.counters["crops"] = static_cast<double>(crops.size());
}
BENCHMARK(BM_EncodeCrop)
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({2, 1})
    ->Args({2, 2})
    ->Args({2, 3})
    ->Args({2, 4})
    ->Args({2, 5})
    ->Args({2, 6})
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
