#pragma once
// Small sample sets for the programs' tests (rdsf-train one process and under mpirun): crops of a standing
// figure (head, body, legs) or of a box at some depth, easy to tell apart, written with SampleSetWriter.
#include <cstdint>
#include <random>
#include <string>

#include <opencv2/imgproc.hpp>

#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/features/feature_spec.hpp"

namespace rdsf::test {

// A standing figure (head, body, legs) or a box at some depth: easy to tell apart.
inline cv::Mat1w crop(bool person, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> shift(-4, 4), depth(1500, 4500), size(10, 40);
  cv::Mat1w out(128, 64, std::uint16_t{0});
  const auto d = static_cast<std::uint16_t>(depth(rng));
  const int dx = shift(rng);
  if (person) {
    cv::ellipse(out, cv::Point(32 + dx, 14), cv::Size(7, 9), 0, 0, 360, d, cv::FILLED);
    cv::rectangle(out, cv::Rect(20 + dx, 24, 24, 46), d, cv::FILLED);
    cv::rectangle(out, cv::Rect(22 + dx, 70, 8, 54), d, cv::FILLED);
    cv::rectangle(out, cv::Rect(34 + dx, 70, 8, 54), d, cv::FILLED);
  } else {
    const int w = size(rng), h = size(rng);
    cv::rectangle(out, cv::Rect(16 + dx, 128 - h - 2 * size(rng), w, h), d, cv::FILLED);
  }
  return out;
}

/// `count` samples of one label from recording `source`, frames 0 .. count - 1 (named `frame_prefix` + number).
inline void make_set(const std::string& dir, int label, int count, std::uint64_t seed, const FeatureSpec& spec = {},
                     const std::string& source = "test", const std::string& frame_prefix = "") {
  SampleSetWriter writer = SampleSetWriter::open_or_create(dir, spec, CameraModel{}, "test");
  std::mt19937_64 rng(seed);
  for (int i = 0; i < count; ++i) {
    SampleRecord r;
    r.label = label;
    r.origin = "labeler";
    r.source = source;
    r.frame = frame_prefix + std::to_string(i);
    r.strict_box = cv::Rect(i, 0, 10, 20);
    r.window = r.strict_box;
    writer.append(r, crop(label == 1, rng));
  }
}

}  // namespace rdsf::test
