#include "rdsf/segmentation/background_model.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "rdsf/core/durable_io.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/frame_buffers.hpp"
#include "rdsf/frame/camera_file.hpp"
#include "rdsf/frame/depth_png.hpp"

namespace rdsf {

namespace fs = std::filesystem;

const ParameterTable<BackgroundParams>& background_parameters() {
  using P = BackgroundParams;
  static const ParameterTable<P> table = {
      parameter("background-margin", &P::margin_mm,
                "with --background: a pixel is in front of the room when nearer than its background by more than "
                "this (mm) ...",
                Range::between(0, 10000)),
      parameter("background-relative", &P::margin_relative,
                "... and by more than this fraction of the background's depth (Kinect noise grows with depth)",
                Range::between(0, 1)),
  };
  return table;
}

void BackgroundModel::check_fits(const DepthFrame& frame) const {
  const std::string where = "background " + (path.empty() ? std::string("(in memory)") : path);
  if (frame.depth_mm.cols != far_mm.cols || frame.depth_mm.rows != far_mm.rows) {
    fail(where, "learned from " + std::to_string(far_mm.cols) + "x" + std::to_string(far_mm.rows) + " frames, but frame " +
                    frame.name + " is " + std::to_string(frame.depth_mm.cols) + "x" + std::to_string(frame.depth_mm.rows));
  }
  if (!(frame.camera == camera)) {
    fail(where, "learned with camera " + camera.describe() + ", but frame " + frame.name + " has " +
                    frame.camera.describe());
  }
}

namespace {

// The rule in whole millimetres: margin = max(M, (b * R + 32768) >> 16) with M = round(margin_mm),
// R = round(margin_relative * 65536) (b * R < 2^32 for b < 2^16, R <= 2^16), and d is in front when d > 0 and
// (b == 0 or d + margin < b); front[c] is 0xff or 0.
// With SSE2 and R < 2^16 (margin_relative below 1) eight pixels at a time in 16-bit lanes, exactly: the
// rounded product is the high half of b * R plus the top bit of its low half; M <= 10000 and the relative
// part <= b fit 16 bits; d + margin saturates at 65535, which is never below a b < 2^16, as the exact sum
// (>= 65535) is not. The rest of a row, and R = 2^16, in 32 bits one pixel at a time.
struct FrontRule {
  std::uint32_t margin_mm, relative_q16;
  explicit FrontRule(const BackgroundParams& p)
      : margin_mm(static_cast<std::uint32_t>(std::lround(p.margin_mm))),
        relative_q16(static_cast<std::uint32_t>(std::lround(p.margin_relative * 65536.0))) {}
  std::uint8_t pixel(std::uint32_t depth, std::uint32_t room) const {
    const std::uint32_t relative = (room * relative_q16 + 32768u) >> 16;
    const std::uint32_t margin = relative > margin_mm ? relative : margin_mm;
    return static_cast<std::uint8_t>(-static_cast<int>((depth != 0) & ((room == 0) | (depth + margin < room))));
  }
  void row(const std::uint16_t* d, const std::uint16_t* b, std::uint8_t* front, int n) const {
    int c = 0;
#ifdef __SSE2__
    if (relative_q16 < 65536u && margin_mm < 65536u) {
      const __m128i r = _mm_set1_epi16(static_cast<short>(relative_q16)), m = _mm_set1_epi16(static_cast<short>(margin_mm));
      const __m128i zero = _mm_setzero_si128();
      for (; c + 16 <= n; c += 16) {
        __m128i halves[2];
        for (int h = 0; h < 2; ++h) {
          const __m128i depth = _mm_loadu_si128(reinterpret_cast<const __m128i*>(d + c + 8 * h));
          const __m128i room = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b + c + 8 * h));
          const __m128i relative =
              _mm_add_epi16(_mm_mulhi_epu16(room, r), _mm_srli_epi16(_mm_mullo_epi16(room, r), 15));
          const __m128i margin = _mm_add_epi16(_mm_subs_epu16(relative, m), m);  // max(relative, M)
          const __m128i sum = _mm_adds_epu16(depth, margin);
          const __m128i below = _mm_cmpeq_epi16(_mm_subs_epu16(room, sum), zero);  // not sum < room
          const __m128i no_room = _mm_cmpeq_epi16(room, zero), no_depth = _mm_cmpeq_epi16(depth, zero);
          halves[h] = _mm_andnot_si128(no_depth, _mm_or_si128(no_room, _mm_andnot_si128(below, _mm_set1_epi16(-1))));
        }
        _mm_storeu_si128(reinterpret_cast<__m128i*>(front + c), _mm_packs_epi16(halves[0], halves[1]));
      }
    }
#endif
    for (; c < n; ++c) front[c] = pixel(d[c], b[c]);
  }
};

// Each front layer's pixel count, depth sum, nearest and farthest depth, a front pixel at a time (about a tenth
// of a frame's pixels are in front; the integer sums do not depend on the order).
struct LayerSums {
  std::vector<std::uint64_t> sum;
  std::vector<std::int64_t> pixels;
  std::vector<std::uint16_t> nearest, farthest;
  explicit LayerSums(std::size_t count) : sum(count, 0), pixels(count, 0), nearest(count, 65535), farthest(count, 0) {}
  void add(std::size_t k, std::uint16_t d) {
    ++pixels[k];
    sum[k] += d;
    nearest[k] = std::min(nearest[k], d);
    farthest[k] = std::max(farthest[k], d);
  }
};

}  // namespace

cv::Mat1b foreground_mask(const cv::Mat1w& depth_mm, const cv::Mat1w& background_mm, const BackgroundParams& params) {
  if (depth_mm.size() != background_mm.size()) fail("foreground_mask", "depth and background differ in size");
  const FrontRule rule(params);
  cv::Mat1b mask(depth_mm.size());
  for (int r = 0; r < depth_mm.rows; ++r) {
    rule.row(depth_mm.ptr<std::uint16_t>(r), background_mm.ptr<std::uint16_t>(r), mask.ptr<std::uint8_t>(r), depth_mm.cols);
  }
  return mask;
}

Segmentation in_front_of(const Segmentation& segmentation, const cv::Mat1w& depth_mm, const cv::Mat1w& background_mm,
                         const BackgroundParams& params) {
  if (depth_mm.size() != background_mm.size() || depth_mm.size() != segmentation.labels.size()) {
    fail("in_front_of", "depth, background and labels differ in size");
  }
  const FrontRule rule(params);
  const int cols = depth_mm.cols;  // a local: the byte stores below could alias the Mat's fields
  std::vector<std::uint8_t> front(static_cast<std::size_t>(cols));
  Segmentation out;
  out.layers = segmentation.layers;
  out.seeds_mm = segmentation.seeds_mm;
  out.iterations = segmentation.iterations;
  out.labels = frame_buffer(FrameBuffer::in_front_labels, segmentation.labels.size(), CV_8UC1);  // every pixel written
  const std::size_t count = out.layers.size() + 1;
  LayerSums sums(count);
  for (int r = 0; r < depth_mm.rows; ++r) {
    const std::uint8_t* in = segmentation.labels.ptr<std::uint8_t>(r);
    const std::uint16_t* b = background_mm.ptr<std::uint16_t>(r);
    const std::uint16_t* d = depth_mm.ptr<std::uint16_t>(r);
    std::uint8_t* label = out.labels.ptr<std::uint8_t>(r);
    rule.row(d, b, front.data(), cols);
    for (int c = 0; c < cols; ++c) label[c] = in[c] & front[c];
    const auto take = [&](int x) {  // a front pixel's label: a layer's (summed) or beyond the layers (dropped)
      const std::uint8_t k = label[x];
      if (k >= count) {
        label[x] = 0;
      } else if (k != 0) {
        sums.add(k, d[x]);
      }
    };
    int c = 0;
#ifdef __SSE2__
    const __m128i zero = _mm_setzero_si128();
    for (; c + 16 <= cols; c += 16) {  // sixteen labels at a time: most are 0 (no reading or not in front)
      auto set = ~static_cast<unsigned>(
                     _mm_movemask_epi8(_mm_cmpeq_epi8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(label + c)), zero))) &
                 0xffffu;
      for (; set != 0; set &= set - 1) take(c + __builtin_ctz(set));
    }
#endif
    for (; c < cols; ++c) take(c);
  }
  for (DepthLayer& layer : out.layers) {
    const auto k = static_cast<std::size_t>(layer.label);
    if (k >= count) continue;
    layer.pixel_count = sums.pixels[k];
    if (sums.pixels[k] == 0) continue;
    layer.mean_depth_mm = static_cast<double>(sums.sum[k]) / static_cast<double>(sums.pixels[k]);
    layer.min_depth_mm = sums.nearest[k];
    layer.max_depth_mm = sums.farthest[k];
  }
  return out;
}

BackgroundLearner::BackgroundLearner(double quantile) : quantile_(quantile) {
  if (!(quantile >= 0.0 && quantile <= 1.0)) fail("background", "the quantile must be in [0, 1]");
}

void BackgroundLearner::add(const DepthFrame& frame) {
  if (frame.depth_mm.empty()) fail("frame " + frame.name, "has no depth image");
  if (frames_.empty()) {
    camera_ = frame.camera;
    first_name_ = frame.name;
  } else if (frame.depth_mm.size() != frames_.front().size() || !(frame.camera == camera_)) {
    fail("frame " + frame.name, std::to_string(frame.depth_mm.cols) + "x" + std::to_string(frame.depth_mm.rows) + " " +
                                    frame.camera.describe() + ", but the background is learned from " +
                                    first_name_ + "'s " + camera_.describe());
  }
  frames_.push_back(frame.depth_mm.clone());
}

BackgroundModel BackgroundLearner::model() const {
  if (frames_.empty()) fail("background", "no frames to learn from");
  BackgroundModel model;
  model.camera = camera_;
  const cv::Size size = frames_.front().size();
  model.far_mm.create(size);
  std::vector<std::uint16_t> readings;
  readings.reserve(frames_.size());
  for (int r = 0; r < size.height; ++r) {
    std::uint16_t* out = model.far_mm.ptr<std::uint16_t>(r);
    for (int c = 0; c < size.width; ++c) {
      readings.clear();
      for (const cv::Mat1w& frame : frames_) {
        const std::uint16_t d = frame.ptr<std::uint16_t>(r)[c];
        if (d != 0) readings.push_back(d);
      }
      if (readings.empty()) {
        out[c] = 0;
        continue;
      }
      const auto rank = static_cast<std::ptrdiff_t>(std::floor(quantile_ * static_cast<double>(readings.size() - 1)));
      std::nth_element(readings.begin(), readings.begin() + rank, readings.end());
      out[c] = readings[static_cast<std::size_t>(rank)];
    }
  }
  return model;
}

std::vector<std::int64_t> evenly_spaced(std::int64_t total, std::int64_t count) {
  std::vector<std::int64_t> out;
  if (total <= 0 || count <= 0) return out;
  if (count >= total) {
    for (std::int64_t i = 0; i < total; ++i) out.push_back(i);
    return out;
  }
  if (count == 1) return {0};
  for (std::int64_t i = 0; i < count; ++i) {
    out.push_back(static_cast<std::int64_t>(std::llround(static_cast<double>(i) * static_cast<double>(total - 1) /
                                                         static_cast<double>(count - 1))));
  }
  return out;
}

void write_background(const std::string& dir, const BackgroundModel& model, bool overwrite) {
  const std::string depth = (fs::path(dir) / BackgroundModel::kDepthFileName).string();
  const std::string camera = (fs::path(dir) / CameraFile::kFileName).string();
  if (!overwrite) {
    for (const std::string& file : {depth, camera}) {
      if (fs::exists(file)) fail(file, "already exists");
    }
  }
  if (model.far_mm.empty() || model.far_mm.cols != model.camera.width_px || model.far_mm.rows != model.camera.height_px) {
    fail(dir, "the background's image is not of its camera model's size");
  }
  create_folders_durably(dir);
  write_png_atomically(depth, model.far_mm);
  write_file_durably(camera, camera_file_text(CameraFile{model.camera, 1.0}));
}

BackgroundModel read_background(const std::string& dir) {
  BackgroundModel model;
  model.path = dir;
  const std::string camera = (fs::path(dir) / CameraFile::kFileName).string();
  if (!fs::is_regular_file(camera)) fail(camera, "missing (a background folder holds " + std::string(BackgroundModel::kDepthFileName) + " and camera.yml)");
  const CameraFile file = read_camera_file(camera);
  if (file.depth_unit_mm != 1.0) fail(camera, "a background is stored in millimetres (depth_unit_mm 1)");
  model.camera = file.camera;
  const std::string depth = (fs::path(dir) / BackgroundModel::kDepthFileName).string();
  model.far_mm = read_depth_png(depth);
  if (model.far_mm.cols != model.camera.width_px || model.far_mm.rows != model.camera.height_px) {
    fail(depth, std::to_string(model.far_mm.cols) + "x" + std::to_string(model.far_mm.rows) + ", but " + camera + " says " +
                    model.camera.describe());
  }
  return model;
}

}  // namespace rdsf
