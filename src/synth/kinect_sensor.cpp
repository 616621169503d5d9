#include "rdsf/synth/kinect_sensor.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "rdsf/synth/random.hpp"

namespace rdsf::synth {

KinectSensor::KinectSensor(const CameraModel& camera, KinectSensorParams params)
    : camera_(camera), params_(params) {
  const double sx = camera.width_px / 640.0, sy = camera.height_px / 480.0;
  band_left_ = static_cast<int>(std::lround(params.band_left_px * sx));
  band_right_ = static_cast<int>(std::lround(params.band_right_px * sx));
  band_top_ = static_cast<int>(std::lround(params.band_top_px * sy));
  band_bottom_ = static_cast<int>(std::lround(params.band_bottom_px * sy));
}

bool KinectSensor::in_band(int x, int y) const {
  return x < band_left_ || x >= camera_.width_px - band_right_ || y < band_top_ ||
         y >= camera_.height_px - band_bottom_;
}

SensorProfile KinectSensor::draw_profile(Rng& rng) const {
  SensorProfile profile;
  const KinectSensorParams& p = params_;
  const double xtion = rng.uniform(), eight = rng.uniform();
  const double factor = rng.uniform(p.xtion_noise_min, p.xtion_noise_max);
  const double step = rng.uniform(p.eight_bit_step_min_mm, p.eight_bit_step_max_mm);
  const double offset = rng.uniform(p.eight_bit_offset_min_m, p.eight_bit_offset_max_m);
  if (xtion < p.xtion_share) {
    profile.noise_factor = factor;
    profile.correlated_share = 0.5;
  }
  if (eight < p.eight_bit_share) {
    profile.eight_bit_step_mm = step;
    profile.eight_bit_offset_mm = 1000.0 * offset;
  }
  return profile;
}

namespace {

// One line of `count` pixels starting at `first`, `step` apart (a row: step 1; a column: the row stride).
// Holes of at most max_px pixels between two readings within jump_fraction of each other take the
// nearer end's reading (the value of a capture, 8-bit steps included); then runs of at most max_px
// readings between holes (or a hole and the image's end) are lost.
void close_line(std::uint16_t* first, int count, std::ptrdiff_t step, int max_px, double jump_fraction) {
  auto at = [&](int i) -> std::uint16_t& { return first[static_cast<std::ptrdiff_t>(i) * step]; };
  for (int i = 1; i < count;) {
    if (at(i) != 0 || at(i - 1) == 0) {
      ++i;
      continue;
    }
    int end = i;  // the hole is i..end-1
    while (end < count && at(end) == 0) ++end;
    const int length = end - i;
    if (end < count && length <= max_px) {
      const double left = at(i - 1), right = at(end);
      if (std::abs(left - right) <= jump_fraction * std::min(left, right)) {
        for (int k = i; k < end; ++k) at(k) = (k - i) * 2 < length ? at(i - 1) : at(end);
      }
    }
    i = end;
  }
  for (int i = 0; i < count;) {
    if (at(i) == 0) {
      ++i;
      continue;
    }
    int end = i;
    while (end < count && at(end) != 0) ++end;
    const bool hole_before = i > 0, hole_after = end < count;  // the image's end counts as a hole
    if (end - i <= max_px && (hole_before || hole_after)) {
      for (int k = i; k < end; ++k) at(k) = 0;
    }
    i = end;
  }
}

}  // namespace

namespace {

// The field is roughly normal around 0.5 (sigma about 0.13): a dropout d removes about d of a surface when
// the field is thresholded at its d-quantile (logistic approximation of the normal quantile).
double field_threshold(double d) {
  if (d >= 0.999) return 2.0;
  if (d <= 0.0) return -1.0;
  return 0.5 + 0.13 * 0.5513 * std::log(d / (1.0 - d));
}

// Dropout per surface: room surfaces, then shapes (in RoomSurface order: floor, ceiling, left, right, front,
// back, window, unused; then the shapes), each plus the base dropout.
std::vector<float> surface_dropouts(const Scene& scene, double base_dropout) {
  const float wall = scene.room.wall_dropout;
  std::vector<float> dropout = {scene.room.floor_dropout, wall, wall, wall, wall, wall,
                                2.0f /* glass */,         0.0f};
  for (const Shape& shape : scene.shapes) dropout.push_back(shape.dropout);
  for (float& d : dropout) d += static_cast<float>(base_dropout);
  return dropout;
}

// A smooth random field in [0, 1): two octaves of bilinear value noise (a coarse grid of cells of
// patch_cell_px at 640 px across, and one three times finer); pixels lose their reading where the field is
// below their surface's dropout, which makes blobby patches. Rows are read in turn: start_row(v), then
// value(u) or fine(u).
class DropoutField {
 public:
  DropoutField(Rng& rng, int width, int height, double patch_cell_px)
      : cell_(std::max(4, static_cast<int>(std::lround(patch_cell_px * width / 640.0)))),
        grid_w_(width / cell_ + 2),
        fine_(std::max(2, cell_ / 3)),
        fine_w_(width / fine_ + 2),
        coarse_(static_cast<std::size_t>(grid_w_ * (height / cell_ + 2))),
        detail_(static_cast<std::size_t>(fine_w_ * (height / fine_ + 2))),
        coarse_x_(static_cast<std::size_t>(width)),
        fine_x_(static_cast<std::size_t>(width)),
        coarse_fx_(static_cast<std::size_t>(width)),
        fine_fx_(static_cast<std::size_t>(width)) {
    for (float& value : coarse_) value = static_cast<float>(rng.uniform());
    for (float& value : detail_) value = static_cast<float>(rng.uniform());
    // bilinear interpolation, with the column lookups computed once per image
    for (int u = 0; u < width; ++u) {
      const std::size_t i = static_cast<std::size_t>(u);
      coarse_x_[i] = u / cell_;
      coarse_fx_[i] = static_cast<float>(u - coarse_x_[i] * cell_) / static_cast<float>(cell_);
      fine_x_[i] = u / fine_;
      fine_fx_[i] = static_cast<float>(u - fine_x_[i] * fine_) / static_cast<float>(fine_);
    }
  }

  void start_row(int v) {
    const int coarse_y = v / cell_, fine_y = v / fine_;
    coarse_fy_ = static_cast<float>(v - coarse_y * cell_) / static_cast<float>(cell_);
    fine_fy_ = static_cast<float>(v - fine_y * fine_) / static_cast<float>(fine_);
    coarse_row_ = coarse_.data() + static_cast<std::size_t>(coarse_y * grid_w_);
    fine_row_ = detail_.data() + static_cast<std::size_t>(fine_y * fine_w_);
  }
  /// Both octaves: 0.7 coarse + 0.3 fine.
  float value(int u) const {
    const std::size_t i = static_cast<std::size_t>(u);
    return 0.7f * lerp_row(coarse_row_, grid_w_, coarse_fy_, coarse_x_[i], coarse_fx_[i]) +
           0.3f * lerp_row(fine_row_, fine_w_, fine_fy_, fine_x_[i], fine_fx_[i]);
  }
  /// The fine octave alone.
  float fine(int u) const {
    const std::size_t i = static_cast<std::size_t>(u);
    return lerp_row(fine_row_, fine_w_, fine_fy_, fine_x_[i], fine_fx_[i]);
  }

 private:
  static float lerp_row(const float* g0, int grid_width, float fy, int gx, float fx) {
    const float* a = g0 + gx;
    const float* b = a + grid_width;
    return (a[0] + (a[1] - a[0]) * fx) * (1 - fy) + (b[0] + (b[1] - b[0]) * fx) * fy;
  }

  int cell_, grid_w_, fine_, fine_w_;
  std::vector<float> coarse_, detail_;
  std::vector<int> coarse_x_, fine_x_;
  std::vector<float> coarse_fx_, fine_fx_;
  float coarse_fy_ = 0, fine_fy_ = 0;
  const float* coarse_row_ = nullptr;
  const float* fine_row_ = nullptr;
};

// Projector shadow along a row: scanning right to left, a pixel is hidden from the projector when a pixel to
// its right reaches further left in the projector's image (u - f b / z), by more than 1 + jitter px.
void projector_shadow(const float* z, int width, double fb, double jitter, std::vector<unsigned char>& shadow) {
  double reach = 1e18;
  for (int u = width - 1; u >= 0; --u) {
    const double up = u - fb / z[u];
    shadow[static_cast<std::size_t>(u)] = up > reach + 1.0 + jitter ? 1 : 0;
    reach = std::min(reach, up);
  }
}

}  // namespace

/// What measure() needs for every pixel of one image: the sensor's parameters, the profile's noise and
/// 8-bit capture, the surfaces' dropouts and the random tables.
struct KinectSensor::PixelModel {
  static constexpr int table_size = 4096;
  const KinectSensorParams& p;
  const SensorProfile& profile;
  std::vector<float> normals;  // a table of normal numbers, indexed by random bits per pixel
  std::vector<float> dropout;
  std::vector<double> surface_threshold;
  double noise_per_m2, correlated;
  bool eight_bit;

  /// The reading (mm; 0: none) of pixel u of the row whose ideal depths are z (z_up, z_down: the rows
  /// above and below), with the pixel's random bits r and the dropout field at its row.
  std::uint16_t reading(int u, int width, const float* z, const float* z_up, const float* z_down,
                        std::uint16_t surface, float incidence, std::uint32_t r, const DropoutField& field) const {
    const double ideal = z[u];
    if (ideal < p.min_range_m || ideal > p.max_range_m) return 0;
    // depth edges: a neighbour much nearer (we are the far side) or much farther (near side)
    const float limit = static_cast<float>(p.edge_jump * ideal);
    const float left = u > 0 ? z[u - 1] : z[u], right = u + 1 < width ? z[u + 1] : z[u];
    const float zd = z[u];
    const bool far_side =
        zd - left > limit || zd - right > limit || zd - z_up[u] > limit || zd - z_down[u] > limit;
    const bool near_side =
        left - zd > limit || right - zd > limit || z_up[u] - zd > limit || z_down[u] - zd > limit;
    const double chance = static_cast<double>(r & 0xff) / 256.0;
    if (far_side && chance < p.edge_far_hole) return 0;
    if (near_side && chance < p.edge_near_hole) return 0;
    // block matching smears the near surface over the edge: ragged, slightly fattened silhouettes
    double depth = zd;
    if (far_side && static_cast<double>((r >> 20) & 0xff) / 256.0 < p.edge_fatten) {
      depth = std::min(std::min(left, right), std::min(z_up[u], z_down[u]));
    }
    // blobby dropout by material and viewing angle; the threshold of a surface's own dropout is computed
    // once per image (a logarithm per pixel was a tenth of the time): only pixels seen at a grazing angle
    // need their own
    double drop = dropout[surface];
    double threshold = surface_threshold[surface];
    if (incidence < p.grazing_cosine) {
      drop += 1.2 * (p.grazing_cosine - incidence) / p.grazing_cosine;
      threshold = field_threshold(drop);
    }
    if (drop > 0 && field.value(u) < threshold) return 0;
    // noise and disparity quantisation, both growing with z^2; part of the noise may be shared by
    // neighbouring pixels (the coarse field is about normal around 0.5 with sigma 0.13)
    double unit_noise = normals[(r >> 8) & (table_size - 1)];
    if (correlated > 0) unit_noise = (1.0 - correlated) * unit_noise + correlated * 1.4 * (field.fine(u) - 0.5) / 0.13;
    const double noisy = depth + noise_per_m2 * depth * depth * unit_noise;
    const double steps = std::max(1.0, std::round(p.disparity_scale / noisy));
    const double measured = p.disparity_scale / steps;
    if (measured < p.min_range_m || measured > p.max_range_m) return 0;
    double mm = measured * 1000.0;
    if (eight_bit) {  // an 8-bit linear capture: codes 1..255 (0 is no reading)
      const double code = std::round((mm - profile.eight_bit_offset_mm) / profile.eight_bit_step_mm);
      if (code < 1 || code > 255) return 0;
      mm = profile.eight_bit_offset_mm + code * profile.eight_bit_step_mm;
    }
    return static_cast<std::uint16_t>(std::lround(mm));
  }
};

cv::Mat1w KinectSensor::measure(const Scene& scene, const RenderBuffers& buffers, std::uint64_t seed,
                                const SensorProfile& profile) const {
  const int width = camera_.width_px, height = camera_.height_px;
  Rng rng(seed);
  PixelModel model{params_, profile, std::vector<float>(PixelModel::table_size), surface_dropouts(scene, params_.base_dropout),
                   {}, params_.noise_per_m2 * profile.noise_factor, profile.correlated_share,
                   profile.eight_bit_step_mm > 0};
  for (float& value : model.normals) value = static_cast<float>(rng.normal());
  DropoutField field(rng, width, height, params_.patch_cell_px);
  model.surface_threshold.resize(model.dropout.size());
  for (std::size_t i = 0; i < model.dropout.size(); ++i) model.surface_threshold[i] = field_threshold(model.dropout[i]);

  cv::Mat1w out(height, width, static_cast<std::uint16_t>(0));
  const double fb = camera_.fx_px * params_.baseline_m;
  std::vector<unsigned char> shadow(static_cast<std::size_t>(width));
  for (int v = 0; v < height; ++v) {
    const float* z = buffers.depth_m.ptr<float>(v);
    const float* z_up = buffers.depth_m.ptr<float>(std::max(0, v - 1));
    const float* z_down = buffers.depth_m.ptr<float>(std::min(height - 1, v + 1));
    const std::uint16_t* surface = buffers.surface.ptr<std::uint16_t>(v);
    const float* incidence = buffers.incidence.ptr<float>(v);
    std::uint16_t* depth_mm = out.ptr<std::uint16_t>(v);
    field.start_row(v);
    projector_shadow(z, width, fb, 0.7 * std::abs(rng.normal()), shadow);
    // two pixels' random bits from each draw
    std::uint64_t bits = rng.next();
    int bits_left = 2;
    for (int u = 0; u < width; ++u) {
      if (bits_left == 0) {
        bits = rng.next();
        bits_left = 2;
      }
      const std::uint32_t r = static_cast<std::uint32_t>(bits & 0xffffffffU);
      bits >>= 32;
      --bits_left;
      if (u < band_left_ || u >= width - band_right_ || v < band_top_ || v >= height - band_bottom_) continue;
      if (shadow[static_cast<std::size_t>(u)]) continue;
      depth_mm[u] = model.reading(u, width, z, z_up, z_down, surface[u], incidence[u], r, field);
    }
  }
  if (params_.coherent_holes_px > 0) make_holes_coherent(out, params_.coherent_holes_px, params_.edge_jump);
  return out;
}

void KinectSensor::make_holes_coherent(cv::Mat1w& depth_mm, int max_px, double jump_fraction) {
  if (max_px <= 0 || depth_mm.empty()) return;
  const std::ptrdiff_t stride = static_cast<std::ptrdiff_t>(depth_mm.step1());
  for (int v = 0; v < depth_mm.rows; ++v) close_line(depth_mm.ptr<std::uint16_t>(v), depth_mm.cols, 1, max_px, jump_fraction);
  for (int u = 0; u < depth_mm.cols; ++u) {
    close_line(depth_mm.ptr<std::uint16_t>(0) + u, depth_mm.rows, stride, max_px, jump_fraction);
  }
}

}  // namespace rdsf::synth
