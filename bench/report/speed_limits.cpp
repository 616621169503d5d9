#include "speed_limits.hpp"

#include "report_clock.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <sstream>
#include <thread>
#include <vector>

#include <libdeflate.h>

#include "bench/bench_scene.hpp"
#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/features/rdsf_extractor.hpp"
#include "rdsf/frame/depth_png.hpp"
#include "rdsf/frame/png_decoder.hpp"
#include "rdsf/frame/png_folder_source.hpp"
#include "rdsf/segmentation/depth_layers.hpp"
#include "rdsf/synth/synth_sequence.hpp"

namespace rdsf::perf {
namespace {

using clock::Clock;
using clock::seconds_since;

// The fastest of `passes` runs of `work` (seconds).
template <typename Work>
double best_of(int passes, const Work& work) {
  double best = std::numeric_limits<double>::infinity();
  for (int p = 0; p < passes; ++p) {
    const Clock::time_point t = Clock::now();
    work();
    best = std::min(best, seconds_since(t));
  }
  return best;
}

std::string times(double ratio) { return clock::fixed(ratio, ratio < 10 ? 2 : 1) + "x"; }

// The same with the processor time of the calling thread: the one-thread figures without the wait for
// cores that other work on a shared machine holds.
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <typename Work>
double best_cpu_of(int passes, const Work& work) {
  double best = std::numeric_limits<double>::infinity();
  for (int p = 0; p < passes; ++p) {
    const double t = thread_cpu_seconds();
    work();
    best = std::min(best, thread_cpu_seconds() - t);
  }
  return best;
}

// Reading PNG files by the direct path and by cv::imdecode, the two alternated twice: each figure is the
// best of `passes` passes over all of `paths` (processor time), in ms per file. `inflate_ms`: libdeflate's
// inflate alone of the files' zlib streams (in memory), depth and colour, per frame: the direct path's floor.
void time_png_reading(const std::vector<std::string>& depth, const std::vector<std::string>& colour, int passes,
                      double& depth_direct_ms, double& depth_imdecode_ms, double& colour_direct_ms,
                      double& colour_imdecode_ms, double& inflate_ms) {
  const PngDecodeOptions direct{true}, reference{false};
  const auto best = [&](double& into, const std::vector<std::string>& paths, const PngDecodeOptions& how) {
    const double ms = 1e3 * best_cpu_of(passes, [&] {
      for (const std::string& path : paths) read_png_file(path, how);
    }) / static_cast<double>(paths.size());
    into = into == 0 ? ms : std::min(into, ms);
  };
  std::vector<std::vector<unsigned char>> streams;
  std::size_t largest = 0;
  for (const auto* paths : {&depth, &colour}) {
    for (const std::string& path : *paths) {
      std::ifstream in(path, std::ios::binary);
      const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      streams.push_back(png_zlib_stream(path, bytes.data(), bytes.size()));
      const cv::Mat image = read_png_file(path);
      largest = std::max(largest, image.total() * image.elemSize() + static_cast<std::size_t>(image.rows));
    }
  }
  std::vector<unsigned char> out(largest);  // the rows and their filter bytes
  libdeflate_decompressor* inflater = libdeflate_alloc_decompressor();
  for (int round = 0; round < 2; ++round) {
    best(depth_direct_ms, depth, direct);
    best(depth_imdecode_ms, depth, reference);
    best(colour_direct_ms, colour, direct);
    best(colour_imdecode_ms, colour, reference);
    const double ms = 1e3 * best_cpu_of(passes, [&] {
      for (const auto& stream : streams) {
        std::size_t got = 0;
        libdeflate_zlib_decompress(inflater, stream.data(), stream.size(), out.data(), out.size(), &got);
      }
    }) / static_cast<double>(depth.size());
    inflate_ms = inflate_ms == 0 ? ms : std::min(inflate_ms, ms);
  }
  libdeflate_free_decompressor(inflater);
}

}  // namespace

double read_bandwidth_gbps(double mib, int threads, int passes) {
  const std::size_t words = static_cast<std::size_t>(mib * 1024 * 1024 / 8);
  std::vector<std::uint64_t> buffer(words);
  for (std::size_t i = 0; i < words; ++i) buffer[i] = i;  // touched: resident before timing
  threads = std::max(1, threads);
  std::vector<std::uint64_t> sink(static_cast<std::size_t>(threads));
  const double seconds = best_of(passes, [&] {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) {
      pool.emplace_back([&, t] {
        const std::size_t begin = words * t / threads, end = words * (t + 1) / threads;
        std::uint64_t a = 0, b = 0, c = 0, d = 0;
        for (std::size_t i = begin; i + 4 <= end; i += 4) {
          a += buffer[i];
          b += buffer[i + 1];
          c += buffer[i + 2];
          d += buffer[i + 3];
        }
        sink[static_cast<std::size_t>(t)] = a + b + c + d;
      });
    }
    for (std::thread& th : pool) th.join();
  });
  volatile std::uint64_t keep = sink[0];
  (void)keep;
  return static_cast<double>(words * 8) / seconds / 1e9;
}

namespace {

using Say = std::function<void(const std::string&)>;

// Streaming-read bandwidth on 1 and o.threads threads, and one pass over a frame (the memory-traffic floor).
void measure_memory(const SpeedLimitOptions& o, const Say& say, SpeedLimits& s) {
  s.stream_buffer_mib = o.quick ? 256 : 1024;
  say("memory bandwidth: streaming reads of " + clock::fixed(s.stream_buffer_mib, 0) + " MiB on 1 and " +
      std::to_string(o.threads) + " threads");
  s.read_gbps_1 = read_bandwidth_gbps(s.stream_buffer_mib, 1, 3);
  s.read_gbps_n = read_bandwidth_gbps(s.stream_buffer_mib, o.threads, 3);

  {  // one pass over a frame: read 16-bit depth, write a byte per pixel (cache-resident, as a frame is)
    cv::Mat1w depth(480, 640);
    cv::randu(depth, 0, 8000);
    cv::Mat1b out(480, 640);
    s.frame_pass_ms = 1e3 * best_cpu_of(o.quick ? 50 : 400, [&] {
      const std::uint16_t* in = depth.ptr<std::uint16_t>(0);
      std::uint8_t* o8 = out.ptr<std::uint8_t>(0);
      for (int i = 0; i < 480 * 640; ++i) o8[i] = static_cast<std::uint8_t>(in[i] >> 8);
    });
  }
}

// PNG reading, direct path against cv::imdecode and libdeflate's inflate alone: a synthetic frame, and the
// real frames of o.real_frames_dir when given.
void measure_png_reading(const SpeedLimitOptions& o, const Say& say, SpeedLimits& s) {
  say("PNG reading: direct path and cv::imdecode on the same synthetic frame");
  const synth::SynthFrame shown = synth::SynthSequence(bench::bench_scene(1, /*rgb=*/true)).frame(0);
  const auto dir = std::filesystem::temp_directory_path() / ("rdsf-speed-limits-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string depth_png = (dir / "0.depth.png").string(), colour_png = (dir / "0.rgb.png").string();
  write_png_atomically(depth_png, shown.depth_mm);
  write_png_atomically(colour_png, shown.bgr);
  const int reps = o.quick ? 5 : 30;
  time_png_reading({depth_png}, {colour_png}, reps, s.png_depth_direct_ms, s.png_depth_imdecode_ms,
                   s.png_colour_direct_ms, s.png_colour_imdecode_ms, s.png_inflate_ms);
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  if (!o.real_frames_dir.empty()) {
    // The frames of the folder as a frame source delivers them, those with a colour image.
    std::vector<std::string> depth, colour;
    const PngFolderSource folder(o.real_frames_dir, CameraModel::kinect_v1());
    for (const std::string& path : folder.depth_paths()) {
      const std::string rgb = PngFolderSource::colour_path(path);
      if (rgb.empty() || !std::filesystem::exists(rgb, ec)) continue;
      depth.push_back(path);
      colour.push_back(rgb);
      if (o.quick && depth.size() == 4) break;
    }
    s.real_frames_dir = o.real_frames_dir;
    s.real_frames = static_cast<int>(depth.size());
    say("PNG reading: direct path and cv::imdecode on the " + std::to_string(depth.size()) + " real frames of " +
        o.real_frames_dir);
    if (!depth.empty()) {
      time_png_reading(depth, colour, o.quick ? 1 : 3, s.real_depth_direct_ms, s.real_depth_imdecode_ms,
                       s.real_colour_direct_ms, s.real_colour_imdecode_ms, s.real_inflate_ms);
    }
  }
}

// Segmentation per frame, candidates per candidate and the full vector per candidate, one thread.
void measure_stages(const SpeedLimitOptions& o, const Say& say, SpeedLimits& s) {
  s.frames = o.quick ? 8 : o.frames;
  say("segmentation, candidates and the full vector on " + std::to_string(s.frames) + " synthetic frames, one thread");
  const synth::SynthParams p = synth::people_scene(s.frames, 1, 4, 17);
  synth::SynthSequence sequence(p);
  std::vector<DepthFrame> frames;
  for (int i = 0; i < s.frames; ++i) {
    DepthFrame f;
    f.depth_mm = sequence.frame(i).depth_mm;
    frames.push_back(f);
  }
  std::vector<Segmentation> segmentations(frames.size());
  const int passes = o.quick ? 2 : 5;
  s.segmentation_ms = 1e3 * best_cpu_of(passes, [&] {
    for (std::size_t i = 0; i < frames.size(); ++i) segmentations[i] = segment_depth(frames[i].depth_mm, {});
  }) / static_cast<double>(frames.size());
  std::vector<Candidate> all;
  const CandidateParams cp;
  const double candidates_s = best_cpu_of(passes, [&] {
    all.clear();
    for (std::size_t i = 0; i < frames.size(); ++i) {
      for (Candidate& c : find_candidates(frames[i], segmentations[i], cp)) all.push_back(std::move(c));
    }
  });
  s.candidates = static_cast<long long>(all.size());
  s.candidates_ms_per_candidate = all.empty() ? 0 : 1e3 * candidates_s / static_cast<double>(all.size());
  const RdsfExtractor extractor;
  std::vector<float> vector(static_cast<std::size_t>(extractor.dimension()));
  const double vector_s = best_cpu_of(passes, [&] {
    for (const Candidate& c : all) extractor.compute(c.depth_crop, vector.data());
  });
  s.full_vector_us = all.empty() ? 0 : 1e6 * vector_s / static_cast<double>(all.size());
}

}  // namespace

SpeedLimits measure_speed_limits(const SpeedLimitOptions& o) {
  SpeedLimits s;
  s.threads = o.threads;
  s.load_start = clock::load_average_now();
  const Say say = [](const std::string& text) { std::cerr << "speed limits: " << text << std::endl; };
  measure_memory(o, say, s);
  measure_png_reading(o, say, s);
  measure_stages(o, say, s);
  s.load_end = clock::load_average_now();
  return s;
}

std::string speed_limits_markdown(const SpeedLimits& s) {
  std::ostringstream m;
  const double frame_bytes = 640.0 * 480 * 3;  // 2 B read + 1 B written per pixel
  const double frame_dram_ms = 1e3 * frame_bytes / (s.read_gbps_1 * 1e9);
  m << "\n#### Speed against the machine's limits (issue 17)\n\n"
    << "Measured in the same run, one thread unless said, best of several passes; the one-thread figures are "
    << "the processor time of the measuring thread (the cores are shared), the bandwidth is wall time (load average "
    << s.load_start << " at the start of this section, " << s.load_end << " at its end).\n\n"
    << "| Measure | This run | Limit on this machine | Ratio |\n|---|---|---|---|\n"
    << "| Memory bandwidth, streaming reads of " << clock::fixed(s.stream_buffer_mib, 0) << " MiB | " << clock::fixed(s.read_gbps_1, 1)
    << " GB/s on 1 thread, " << clock::fixed(s.read_gbps_n, 1) << " GB/s on " << s.threads << " | - | - |\n"
    << "| One pass over a 640x480 frame (614,400 B of depth read, 307,200 B written) | " << clock::fixed(s.frame_pass_ms, 3)
    << " ms (frame in cache) | " << clock::fixed(frame_dram_ms, 3) << " ms at the streaming rate | - |\n"
    << "| Segmentation per frame (" << s.frames << " synthetic frames, 1..4 people) | " << clock::fixed(s.segmentation_ms, 3)
    << " ms | one pass " << clock::fixed(s.frame_pass_ms, 3) << " ms; target 0.3 ms | "
    << times(s.segmentation_ms / s.frame_pass_ms) << " one pass |\n"
    << "| Candidates (" << s.candidates << " in the " << s.frames << " frames, depth only) | "
    << clock::fixed(s.frames > 0 ? s.candidates_ms_per_candidate * static_cast<double>(s.candidates) / s.frames : 0.0, 3)
    << " ms per frame = " << clock::fixed(s.candidates_ms_per_candidate, 4) << " ms per candidate | target 0.05 ms per "
    << "candidate: the stage's figure above (denser frames share the per-frame part, the column runs, among more) | - |\n"
    << "| Full 8128 RDSF vector per candidate | " << clock::fixed(s.full_vector_us, 1) << " us | target 20 us | - |\n"
    << "| Depth PNG (16-bit, 640x480) read and decoded | direct " << clock::fixed(s.png_depth_direct_ms, 2) << " ms | cv::imdecode "
    << clock::fixed(s.png_depth_imdecode_ms, 2) << " ms | " << times(s.png_depth_imdecode_ms / s.png_depth_direct_ms)
    << " faster |\n"
    << "| Colour PNG (8-bit RGB, 640x480) read and decoded | direct " << clock::fixed(s.png_colour_direct_ms, 2)
    << " ms | cv::imdecode " << clock::fixed(s.png_colour_imdecode_ms, 2) << " ms | "
    << times(s.png_colour_imdecode_ms / s.png_colour_direct_ms) << " faster |\n"
    << "| Both PNGs of a frame | direct " << clock::fixed(s.png_depth_direct_ms + s.png_colour_direct_ms, 2)
    << " ms | cv::imdecode " << clock::fixed(s.png_depth_imdecode_ms + s.png_colour_imdecode_ms, 2) << " ms | "
    << times((s.png_depth_imdecode_ms + s.png_colour_imdecode_ms) / (s.png_depth_direct_ms + s.png_colour_direct_ms))
    << " faster (rdsf-synth's noisy colour: libdeflate's inflate alone is most of it) |\n"
    << "| Both PNGs of a frame, libdeflate's inflate alone (the direct path's floor) | " << clock::fixed(s.png_inflate_ms, 2)
    << " ms | direct " << clock::fixed(s.png_depth_direct_ms + s.png_colour_direct_ms, 2) << " ms | direct at "
    << times((s.png_depth_direct_ms + s.png_colour_direct_ms) / s.png_inflate_ms) << " the floor |\n";
  if (s.real_frames > 0) {
    const double direct = s.real_depth_direct_ms + s.real_colour_direct_ms;
    const double reference = s.real_depth_imdecode_ms + s.real_colour_imdecode_ms;
    m << "| Real frames (" << s.real_frames << " of " << s.real_frames_dir << "), depth PNG, mean per frame | direct "
      << clock::fixed(s.real_depth_direct_ms, 2) << " ms | cv::imdecode " << clock::fixed(s.real_depth_imdecode_ms, 2)
      << " ms | " << times(s.real_depth_imdecode_ms / s.real_depth_direct_ms) << " faster |\n"
      << "| Real frames, colour PNG, mean per frame | direct " << clock::fixed(s.real_colour_direct_ms, 2)
      << " ms | cv::imdecode " << clock::fixed(s.real_colour_imdecode_ms, 2) << " ms | "
      << times(s.real_colour_imdecode_ms / s.real_colour_direct_ms) << " faster |\n"
      << "| Real frames, both PNGs | direct " << clock::fixed(direct, 2) << " ms | cv::imdecode "
      << clock::fixed(reference, 2) << " ms | " << times(reference / direct) << " faster (target 3x: "
      << (reference >= 3 * direct ? "met" : "not met") << ") |\n"
      << "| Real frames, both PNGs, libdeflate's inflate alone (the direct path's floor) | " << clock::fixed(s.real_inflate_ms, 2)
      << " ms | direct " << clock::fixed(direct, 2) << " ms | direct at " << times(direct / s.real_inflate_ms)
      << " the floor |\n";
  } else {
    m << "| Real frames | not measured: no folder of real frames (--real-frames) | - | - |\n";
  }
  return m.str();
}

std::string speed_limits_summary(const SpeedLimits& s) {
  std::ostringstream m;
  m << "memory bandwidth " << clock::fixed(s.read_gbps_1, 1) << " GB/s (1 thread), " << clock::fixed(s.read_gbps_n, 1) << " GB/s ("
    << s.threads << " threads); segmentation " << clock::fixed(s.segmentation_ms, 3) << " ms per frame (one pass "
    << clock::fixed(s.frame_pass_ms, 3) << " ms), candidates " << clock::fixed(s.candidates_ms_per_candidate, 4)
    << " ms each, full vector " << clock::fixed(s.full_vector_us, 1) << " us; PNG frame "
    << clock::fixed(s.png_depth_direct_ms + s.png_colour_direct_ms, 2) << " ms vs cv::imdecode "
    << clock::fixed(s.png_depth_imdecode_ms + s.png_colour_imdecode_ms, 2) << " ms";
  if (s.real_frames > 0) {
    m << "; real PNG frame " << clock::fixed(s.real_depth_direct_ms + s.real_colour_direct_ms, 2) << " ms vs "
      << clock::fixed(s.real_depth_imdecode_ms + s.real_colour_imdecode_ms, 2) << " ms";
  }
  m << "\n";
  return m.str();
}

}  // namespace rdsf::perf
