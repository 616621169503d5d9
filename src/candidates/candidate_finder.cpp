#include "rdsf/candidates/candidate_finder.hpp"

#include <algorithm>
#include <cmath>

#include "rdsf/candidates/column_heights.hpp"
#include "rdsf/candidates/floor_trim.hpp"
#include "rdsf/candidates/layer_objects.hpp"

namespace rdsf {

double iou(const cv::Rect& a, const cv::Rect& b) {
  const double inter = (a & b).area();
  const double uni = static_cast<double>(a.area()) + b.area() - inter;
  return uni > 0 ? inter / uni : 0.0;
}

void cut_crops(const DepthFrame& frame, const cv::Mat1b& labels, int layer, const cv::Rect& window,
               cv::Size crop_size, Candidate& candidate) {
  candidate.depth_crop.create(crop_size);
  const bool colour = frame.has_colour();
  if (colour) {
    candidate.colour_crop.create(crop_size);
  } else {
    candidate.colour_crop.release();
  }
  // Nearest neighbour: output pixel u samples source column window.x + floor((u + 0.5) * w / W). The
  // source columns grow with u, so those inside the image are the outputs inside..inside_end - 1; the
  // others, and rows outside the image, read 0 (black).
  thread_local std::vector<int> source_x;
  source_x.resize(static_cast<std::size_t>(std::max(0, crop_size.width)));
  int inside = 0, inside_end = 0;
  for (int u = 0; u < crop_size.width; ++u) {
    const int x = window.x + static_cast<int>(std::floor((u + 0.5) * window.width / crop_size.width));
    source_x[static_cast<std::size_t>(u)] = x;
    if (x < 0) inside = u + 1;
    if (x < frame.depth_mm.cols) inside_end = u + 1;
  }
  inside_end = std::max(inside, inside_end);
  const int* const xs = source_x.data();
  const cv::Vec3b black(0, 0, 0);
  for (int v = 0; v < crop_size.height; ++v) {
    const int y = window.y + static_cast<int>(std::floor((v + 0.5) * window.height / crop_size.height));
    std::uint16_t* depth_out = candidate.depth_crop.ptr<std::uint16_t>(v);
    cv::Vec3b* colour_out = colour ? candidate.colour_crop.ptr<cv::Vec3b>(v) : nullptr;
    const bool row_inside = y >= 0 && y < frame.depth_mm.rows;
    const int from = row_inside ? inside : crop_size.width, to = row_inside ? inside_end : crop_size.width;
    std::fill(depth_out, depth_out + from, std::uint16_t{0});
    std::fill(depth_out + to, depth_out + crop_size.width, std::uint16_t{0});
    if (colour) {
      std::fill(colour_out, colour_out + from, black);
      std::fill(colour_out + to, colour_out + crop_size.width, black);
    }
    if (!row_inside) continue;
    const std::uint8_t* label_row = labels.ptr<std::uint8_t>(y);
    const std::uint16_t* depth_row = frame.depth_mm.ptr<std::uint16_t>(y);
    if (!colour) {
      for (int u = from; u < to; ++u) {
        const int x = xs[u];
        depth_out[u] = label_row[x] == layer ? depth_row[x] : std::uint16_t{0};
      }
      continue;
    }
    const cv::Vec3b* colour_row = frame.bgr.ptr<cv::Vec3b>(y);
    for (int u = from; u < to; ++u) {
      const int x = xs[u];
      const bool in = label_row[x] == layer;
      depth_out[u] = in ? depth_row[x] : std::uint16_t{0};
      colour_out[u] = in ? colour_row[x] : black;
    }
  }
}

std::vector<Candidate> find_candidates(const DepthFrame& frame, const Segmentation& segmentation,
                                       const CandidateParams& params, cv::Size crop_size) {
  std::vector<Candidate> candidates;
  const int layer_count = static_cast<int>(segmentation.layers.size());
  if (layer_count == 0) return candidates;
  std::vector<int> occlusion_px(static_cast<std::size_t>(layer_count) + 1, 0);
  for (const DepthLayer& layer : segmentation.layers) {
    occlusion_px[static_cast<std::size_t>(layer.label)] = static_cast<int>(
        params.occlusion_gap_cm * 10.0 * frame.camera.fy_px / std::max(1.0, layer.mean_depth_mm));
  }
  const auto runs = column_runs(segmentation.labels, layer_count, params.k, occlusion_px);
  const cv::Rect image(0, 0, frame.depth_mm.cols, frame.depth_mm.rows);

  int objects_before = 0;  // objects of the layers already done: Candidate::object is unique in the frame
  for (const DepthLayer& layer : segmentation.layers) {
    const auto& column = runs[static_cast<std::size_t>(layer.label)];
    const double depth_mm = layer.mean_depth_mm;
    const LayerView view{&column,  &segmentation.labels, &frame.depth_mm, layer.label,
                         depth_mm, static_cast<double>(layer.max_depth_mm), &frame.camera};
    const LayerObjects found = layer_objects(view, params);
    for (const LayerObject& object : found.objects) {
      int bottom = object.bottom;
      const int top = object.top;
      if (params.floor_tolerance_mm > 0) {
        bottom = floor_trimmed_bottom(frame.depth_mm, segmentation.labels, layer.label, object.first, object.last,
                                      top, bottom, params.floor_tolerance_mm, found.passing, layer.min_depth_mm,
                                      layer.max_depth_mm);
      }
      Candidate candidate;
      const int box_height = bottom - top + 1;
      const int box_width = std::max(1, static_cast<int>(std::lround(box_height / 2.0)));
      const cv::Rect strict(object.highest - box_width / 2, top, box_width, box_height);
      candidate.strict_box = strict & image;
      candidate.fitted_box =
          cv::Rect(object.fit_first, object.fit_top, object.fit_last - object.fit_first + 1, bottom - object.fit_top + 1) &
          image;
      const double cx = strict.x + strict.width / 2.0;
      const double cy = strict.y + strict.height / 2.0;
      const int window_width = std::max(1, static_cast<int>(std::lround(strict.width * params.window_scale)));
      const int window_height = std::max(1, static_cast<int>(std::lround(strict.height * params.window_scale)));
      candidate.window_unclipped = cv::Rect(static_cast<int>(std::lround(cx - window_width / 2.0)),
                                            static_cast<int>(std::lround(cy - window_height / 2.0)),
                                            window_width, window_height);
      candidate.window = candidate.window_unclipped & image;
      candidate.layer = layer.label;
      candidate.layer_depth_mm = depth_mm;
      candidate.height_cm = frame.camera.height_cm(object.tallest, depth_mm);
      candidate.width_cm = frame.camera.width_cm(object.last - object.first + 1, depth_mm);
      candidate.highest_column = object.highest;
      candidate.part = object.part;
      candidate.object = objects_before + object.object;
      cut_crops(frame, segmentation.labels, layer.label, candidate.window_unclipped, crop_size, candidate);
      candidates.push_back(std::move(candidate));
    }
    int in_layer = 0;
    for (const LayerObject& object : found.objects) in_layer = std::max(in_layer, object.object + 1);
    objects_before += in_layer;
  }
  return candidates;
}

}  // namespace rdsf
