#include "training_crops.hpp"

#include <algorithm>
#include <chrono>
#include <random>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "rdsf/classifier/real_adaboost.hpp"
#include "rdsf/features/feature_subset.hpp"
#include "rdsf/features/rdsf_extractor.hpp"

namespace rdsf::perf {
namespace {

void noisy_fill(cv::Mat1w& crop, const cv::Mat1b& mask, double depth_mm, double slope_x, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, 25.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int y = 0; y < crop.rows; ++y) {
    for (int x = 0; x < crop.cols; ++x) {
      if (!mask(y, x)) continue;
      if (u(rng) < 0.04) continue;  // missing reading
      const double d = depth_mm + slope_x * (x - 32) + noise(rng);
      crop(y, x) = static_cast<std::uint16_t>(std::clamp(d, 400.0, 9000.0));
    }
  }
}

void add_clutter(cv::Mat1b& mask, std::mt19937_64& rng, int pieces) {
  std::uniform_int_distribution<int> x(0, 63), y(0, 127), w(3, 20), h(3, 40);
  for (int i = 0; i < pieces; ++i) {
    cv::rectangle(mask, cv::Rect(x(rng), y(rng), w(rng), h(rng)), 255, cv::FILLED);
  }
}

cv::Mat1w person_crop(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  cv::Mat1b mask(128, 64, std::uint8_t{0});
  const double s = 0.8 + 0.3 * u(rng);
  const double cx = 32 + (u(rng) - 0.5) * 10, top = 4 + u(rng) * 10;
  auto P = [&](double dx, double dy) { return cv::Point(static_cast<int>(cx + dx * s), static_cast<int>(top + dy * s)); };
  cv::ellipse(mask, P(0, 9), cv::Size(static_cast<int>(7 * s), static_cast<int>(9 * s)), 0, 0, 360, 255, cv::FILLED);
  const double torso_w = 10 + 4 * u(rng);
  cv::rectangle(mask, P(-torso_w, 19), P(torso_w, 62), 255, cv::FILLED);
  const double swing_l = (u(rng) - 0.5) * 14, swing_r = (u(rng) - 0.5) * 14;
  cv::line(mask, P(-torso_w - 2, 22), P(-torso_w - 4 + swing_l, 64), 255, static_cast<int>(5 * s));
  cv::line(mask, P(torso_w + 2, 22), P(torso_w + 4 + swing_r, 64), 255, static_cast<int>(5 * s));
  const double stride = (u(rng) - 0.5) * 22;
  cv::line(mask, P(-5, 62), P(-5 - stride, 112), 255, static_cast<int>(8 * s));
  cv::line(mask, P(5, 62), P(5 + stride, 112), 255, static_cast<int>(8 * s));
  if (u(rng) < 0.3) {  // occluded from below or the side (a table, a chair)
    const int y0 = 60 + static_cast<int>(u(rng) * 50);
    cv::rectangle(mask, cv::Rect(0, y0, 64, 128 - y0), 0, cv::FILLED);
  }
  if (u(rng) < 0.5) add_clutter(mask, rng, 1 + static_cast<int>(u(rng) * 3));
  if (u(rng) < 0.15) add_clutter(mask, rng, 4 + static_cast<int>(u(rng) * 4));  // crowded
  cv::Mat1w crop(128, 64, std::uint16_t{0});
  noisy_fill(crop, mask, 1200 + u(rng) * 5000, (u(rng) - 0.5) * 6, rng);
  return crop;
}

cv::Mat1w clutter_crop(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  cv::Mat1b mask(128, 64, std::uint8_t{0});
  const int kind = static_cast<int>(u(rng) * 7);
  if (kind == 0) {  // pole or door frame: a tall narrow shape, sometimes with a round top (a lamp, a coat stand)
    const int w = 6 + static_cast<int>(u(rng) * 18), x = static_cast<int>(u(rng) * (64 - w));
    cv::rectangle(mask, cv::Rect(x, static_cast<int>(u(rng) * 20), w, 128), 255, cv::FILLED);
    if (u(rng) < 0.5) cv::circle(mask, cv::Point(x + w / 2, 12), 8, 255, cv::FILLED);
  } else if (kind == 1) {  // chair: seat, back, legs
    const int seat = 60 + static_cast<int>(u(rng) * 30);
    cv::rectangle(mask, cv::Rect(8, seat, 48, 8), 255, cv::FILLED);
    cv::rectangle(mask, cv::Rect(8, seat - 40, 8, 40), 255, cv::FILLED);
    cv::rectangle(mask, cv::Rect(8, seat, 5, 128 - seat), 255, cv::FILLED);
    cv::rectangle(mask, cv::Rect(50, seat, 5, 128 - seat), 255, cv::FILLED);
  } else if (kind == 2) {  // table with something on it
    const int top = 50 + static_cast<int>(u(rng) * 40);
    cv::rectangle(mask, cv::Rect(0, top, 64, 10), 255, cv::FILLED);
    cv::rectangle(mask, cv::Rect(4, top, 6, 128 - top), 255, cv::FILLED);
    cv::rectangle(mask, cv::Rect(54, top, 6, 128 - top), 255, cv::FILLED);
    cv::ellipse(mask, cv::Point(20 + static_cast<int>(u(rng) * 24), top - 10), cv::Size(10, 10), 0, 0, 360, 255,
                cv::FILLED);
  } else if (kind == 3) {  // wall piece or cupboard
    const int x0 = static_cast<int>(u(rng) * 40);
    cv::rectangle(mask, cv::Rect(x0, 0, 64 - x0, static_cast<int>(60 + u(rng) * 68)), 255, cv::FILLED);
  } else if (kind == 4) {  // blobs (plants, bags, coats on a hook): can look person-sized
    for (int i = 0; i < 2 + static_cast<int>(u(rng) * 4); ++i) {
      cv::ellipse(mask, cv::Point(static_cast<int>(u(rng) * 64), static_cast<int>(u(rng) * 128)),
                  cv::Size(5 + static_cast<int>(u(rng) * 14), 8 + static_cast<int>(u(rng) * 30)), u(rng) * 180, 0,
                  360, 255, cv::FILLED);
    }
  } else if (kind == 5) {  // random boxes
    add_clutter(mask, rng, 2 + static_cast<int>(u(rng) * 5));
  } else {  // person-like: a coat on a stand, a mannequin-ish column with a round top, no legs
    const double cx = 32 + (u(rng) - 0.5) * 12, top = 4 + u(rng) * 16;
    cv::ellipse(mask, cv::Point(static_cast<int>(cx), static_cast<int>(top + 9)), cv::Size(7, 9), 0, 0, 360, 255,
                cv::FILLED);
    const int half = 8 + static_cast<int>(u(rng) * 10);
    cv::rectangle(mask, cv::Point(static_cast<int>(cx) - half, static_cast<int>(top + 19)),
                  cv::Point(static_cast<int>(cx) + half, static_cast<int>(top + 60 + u(rng) * 60)), 255, cv::FILLED);
  }
  if (u(rng) < 0.5) add_clutter(mask, rng, 1 + static_cast<int>(u(rng) * 2));
  cv::Mat1w crop(128, 64, std::uint16_t{0});
  noisy_fill(crop, mask, 1000 + u(rng) * 5500, (u(rng) - 0.5) * 20, rng);
  return crop;
}

}  // namespace

TrainingRows make_training_rows(int positives, int negatives, std::uint64_t seed, const FeatureSpec& spec,
                                const std::vector<int>& columns) {
  const RdsfExtractor extractor(spec);
  const FeatureSubset subset(spec, columns);
  TrainingRows out;
  out.rows.create(positives + negatives, columns.empty() ? extractor.dimension() : subset.size());
  out.labels.assign(static_cast<std::size_t>(positives + negatives), 0);
  std::mt19937_64 order_rng(seed);
  for (int i = 0; i < positives; ++i) out.labels[static_cast<std::size_t>(i)] = 1;
  std::shuffle(out.labels.begin(), out.labels.end(), order_rng);
  cv::parallel_for_(cv::Range(0, out.rows.rows), [&](const cv::Range& range) {
    for (int r = range.start; r < range.end; ++r) {
      std::mt19937_64 rng(seed * 1000003ULL + static_cast<std::uint64_t>(r));
      const cv::Mat1w crop = out.labels[static_cast<std::size_t>(r)] == 1 ? person_crop(rng) : clutter_crop(rng);
      if (columns.empty()) {
        extractor.compute(crop, out.rows[r]);
      } else {
        subset.compute(crop, out.rows[r]);
      }
    }
  });
  return out;
}

BinnedRows bin_positives_first(const TrainingRows& rows, int threads) {
  const auto start = std::chrono::steady_clock::now();
  BinnedRows out;
  const std::vector<std::size_t> order = positives_first_order(rows.labels);
  out.matrix = BinnedMatrix(rows.rows, BinScheme{}, order, threads);
  for (std::size_t i : order) out.labels.push_back(rows.labels[i]);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace rdsf::perf
