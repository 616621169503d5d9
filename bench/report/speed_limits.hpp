#pragma once
// The machine's limits beside the figures of issue 17, measured in the report's run: memory bandwidth
// (reading a buffer far larger than the caches on 1 and N threads), the one-pass floor of a 640x480 frame
// (read its 16-bit depth, write one byte per pixel), and, on one thread, best of a few passes each:
// reading a frame's PNG files by the direct path and by cv::imdecode (the same files, one after the
// other; also the frames of a folder of real ones when given), segmentation per frame, candidates per candidate and the full 8128 vector per candidate.
#include <string>

namespace rdsf::perf {

struct SpeedLimitOptions {
  bool quick = false;
  int threads = 2;
  int frames = 48;  ///< synthetic frames with 1..4 people for the per-stage figures (quick: 8)
  /// A folder of real NAME.depth.png + NAME.rgb.png frames whose reading is timed too (real recorders'
  /// PNGs use libpng's adaptive filters, nearly all Paeth in colour; rdsf-synth's use Sub); empty: skipped.
  std::string real_frames_dir;
};

struct SpeedLimits {
  int threads = 2;
  double read_gbps_1 = 0, read_gbps_n = 0;  ///< streaming reads, 1 and `threads` threads (GB/s = 1e9 B/s)
  double stream_buffer_mib = 0;
  double frame_pass_ms = 0;  ///< one pass over a 640x480 frame: 614,400 B read, 307,200 B written (1 thread)
  // PNG reading of one synthetic frame, one thread (ms)
  double png_depth_direct_ms = 0, png_depth_imdecode_ms = 0, png_colour_direct_ms = 0, png_colour_imdecode_ms = 0;
  double png_inflate_ms = 0;  // libdeflate's inflate alone of both files' zlib streams (the direct path's floor)
  // ... and of the real frames, the mean per frame of the fastest pass over all of them (ms; 0: none)
  std::string real_frames_dir;
  int real_frames = 0;
  double real_depth_direct_ms = 0, real_depth_imdecode_ms = 0, real_colour_direct_ms = 0, real_colour_imdecode_ms = 0;
  double real_inflate_ms = 0;  // ... per frame, depth and colour
  // Stages, one thread
  int frames = 0;
  long long candidates = 0;
  double segmentation_ms = 0, candidates_ms_per_candidate = 0, full_vector_us = 0;
  std::string load_start, load_end;
};

/// Streaming reads of a `mib` MiB buffer (touched before timing) on `threads` threads, the best of
/// `passes`, in GB/s (1e9 B/s, wall time).
double read_bandwidth_gbps(double mib, int threads, int passes);

/// Measures the above (progress on stderr).
SpeedLimits measure_speed_limits(const SpeedLimitOptions& options);

/// Streaming-read bandwidth (GB/s) of a `mib` MiB buffer on `threads` threads, best of `passes`.
double read_bandwidth_gbps(double mib, int threads, int passes);

/// The Markdown section and the lines for the summary on stdout.
std::string speed_limits_markdown(const SpeedLimits& s);
std::string speed_limits_summary(const SpeedLimits& s);

}  // namespace rdsf::perf
