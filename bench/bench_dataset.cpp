// Speed of sample sets and of the negative miner (issue 4). Targets: loading 30,000 samples and computing
// their features takes under 30 s on 2 cores; mining runs at 100 frames per second or more on 2 cores on
// 640x480 frames (the thesis's pipeline managed 2-3).
//   - BM_LoadSampleSetFeatures: a 30,000-sample set of synthetic 64x128 crops is written once (setup, not
//     timed), then SampleSet::open_read + features() on 2 threads is timed.
//   - BM_MineFrames/threads/colour: rdsf-mine's work on 180 640x480 frames: the real people-free frames of
//     ../shared/realdata/empty, copied 20 times, each copy 1 mm farther so that no crop repeats (else a
//     hand-built scene), with their colour images (colour:1) or depth only (colour:0), mined into a fresh
//     set with 1 or 2 worker threads. Decoding the frame PNGs dominates.
// Run: build/bench/bench_dataset
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "rdsf/dataset/negative_miner.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/frame/frame_source.hpp"

namespace fs = std::filesystem;

namespace {

/// A scratch folder removed at exit (kept when RDSF_BENCH_KEEP is set, to look at or reuse). The exit
/// handler removes a copy of the path that is never destroyed: the handler is registered while the static
/// path is being made, so it runs after that path's destructor.
const fs::path& scratch() {
  static const fs::path dir = [] {
    std::string pattern = (fs::temp_directory_path() / "rdsf-bench-dataset-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) std::abort();
    static const std::string* to_remove = new std::string(pattern);
    if (std::getenv("RDSF_BENCH_KEEP") == nullptr) std::atexit([] {
      std::error_code ec;
      fs::remove_all(*to_remove, ec);
    });
    return fs::path(pattern);
  }();
  return dir;
}

/// A person-like masked crop: an upright ellipse of depth around `depth_mm` with sensor noise on zeros.
cv::Mat1w synthetic_crop(std::mt19937& random) {
  std::uniform_int_distribution<int> depth(800, 6000), noise(-15, 15), shift(-6, 6);
  const int base = depth(random);
  cv::Mat1w crop(128, 64, std::uint16_t{0});
  cv::ellipse(crop, cv::Point(32 + shift(random), 70 + shift(random)), cv::Size(16 + shift(random), 50), 0, 0, 360,
              cv::Scalar(base), cv::FILLED);
  cv::circle(crop, cv::Point(32 + shift(random), 16), 9, cv::Scalar(base - 40), cv::FILLED);
  for (auto& value : crop) {
    if (value != 0) value = static_cast<std::uint16_t>(value + noise(random));
  }
  return crop;
}

const std::string& set_of_30000() {
  static const std::string dir = [] {
    const std::string path = (scratch() / "set30k").string();
    rdsf::SampleSetWriter writer =
        rdsf::SampleSetWriter::open_or_create(path, rdsf::FeatureSpec{}, rdsf::CameraModel::kinect_v1(), "bench");
    std::mt19937 random(7);
    for (int i = 0; i < 30000; ++i) {
      rdsf::SampleRecord record;
      record.label = i % 4 == 0 ? 1 : 0;
      record.origin = "bench";
      record.source = "synthetic";
      record.frame = std::to_string(i);
      writer.append(record, synthetic_crop(random));
    }
    return path;
  }();
  return dir;
}

void BM_LoadSampleSetFeatures(benchmark::State& state) {
  const std::string& dir = set_of_30000();
  const rdsf::RdsfExtractor extractor;
  std::int64_t samples = 0;
  for (auto _ : state) {
    const rdsf::SampleSet set = rdsf::SampleSet::open_read(dir);
    const cv::Mat1f rows = set.features(extractor, {}, static_cast<int>(state.range(0)));
    samples += rows.rows;
    benchmark::DoNotOptimize(rows.data);
  }
  state.counters["samples"] = static_cast<double>(samples) / static_cast<double>(state.iterations());
  state.counters["samples_per_s"] = benchmark::Counter(static_cast<double>(samples), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_LoadSampleSetFeatures)->Arg(2)->ArgName("threads")->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

/// The frames to mine, with their colour images.
const std::string& coloured_frames() {
  static const std::string dir = [] {
    const fs::path out = scratch() / "frames";
    fs::create_directories(out);
    const fs::path empty = fs::path(RDSF_SOURCE_DIR).parent_path() / "shared/realdata/empty";
    std::vector<rdsf::DepthFrame> originals;
    if (fs::is_directory(empty)) {
      auto source = rdsf::open_frame_source(empty.string());
      rdsf::DepthFrame frame;
      while (source->next(frame)) originals.push_back(frame);
      std::fprintf(stderr, "bench_dataset: mining %zu real frames of %s (copied to 180)\n", originals.size(),
                   empty.string().c_str());
    } else {  // boxes and poles before a wall
      std::fprintf(stderr, "bench_dataset: %s is absent: mining a made-up scene of boxes and poles instead\n",
                   empty.string().c_str());
      rdsf::DepthFrame frame;
      frame.depth_mm = cv::Mat1w(480, 640, std::uint16_t{4000});
      frame.depth_mm(cv::Rect(100, 150, 60, 330)).setTo(2000);
      frame.depth_mm(cv::Rect(300, 100, 40, 380)).setTo(2500);
      frame.depth_mm(cv::Rect(450, 200, 120, 280)).setTo(1800);
      frame.bgr = cv::Mat3b(480, 640, cv::Vec3b(90, 120, 150));
      frame.name = "scene";
      originals.push_back(frame);
    }
    int written = 0;
    for (int copy = 0; written < 180; ++copy) {
      for (const rdsf::DepthFrame& frame : originals) {
        // Every copy 1 mm farther: the same real frame, crops that differ (no duplicates).
        cv::Mat1w depth = frame.depth_mm.clone();
        for (auto& value : depth) {
          if (value != 0) value = static_cast<std::uint16_t>(value + copy);
        }
        char name[64];
        std::snprintf(name, sizeof name, "%04d_%s", written++, frame.name.c_str());
        cv::imwrite((out / (std::string(name) + ".depth.png")).string(), depth);
        if (frame.has_colour()) cv::imwrite((out / (std::string(name) + ".rgb.png")).string(), frame.bgr);
      }
    }
    return out.string();
  }();
  return dir;
}

/// The same frames without their colour images (as from depth-only recordings).
const std::string& depth_only_frames() {
  static const std::string dir = [] {
    const std::string& coloured = coloured_frames();
    const fs::path out = scratch() / "frames-depth-only";
    fs::create_directories(out);
    for (const fs::directory_entry& entry : fs::directory_iterator(coloured)) {
      const std::string name = entry.path().filename().string();
      if (name.find(".depth.png") != std::string::npos) fs::create_symlink(entry.path(), out / name);
    }
    return out.string();
  }();
  return dir;
}

void BM_MineFrames(benchmark::State& state) {
  const std::string& frames = state.range(1) != 0 ? coloured_frames() : depth_only_frames();
  static int run = 0;  // a fresh set for every run, across the benchmark's repetitions
  std::int64_t mined = 0, kept = 0;
  for (auto _ : state) {
    state.PauseTiming();
    const std::string set_dir = (scratch() / ("mined" + std::to_string(run++))).string();
    rdsf::SampleSetWriter writer =
        rdsf::SampleSetWriter::open_or_create(set_dir, rdsf::FeatureSpec{}, rdsf::CameraModel::kinect_v1(), "bench");
    rdsf::MineParams params;
    params.sources = {frames};
    params.threads = static_cast<int>(state.range(0));
    state.ResumeTiming();
    const rdsf::MineStats stats = rdsf::mine_negatives(params, writer);
    mined += stats.frames;
    kept += stats.kept;
  }
  state.counters["frames_per_s"] = benchmark::Counter(static_cast<double>(mined), benchmark::Counter::kIsRate);
  state.counters["kept_per_frame"] = static_cast<double>(kept) / static_cast<double>(mined);
}
BENCHMARK(BM_MineFrames)
    ->Args({1, 1})
    ->Args({2, 1})
    ->Args({2, 0})
    ->ArgNames({"threads", "colour"})
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
