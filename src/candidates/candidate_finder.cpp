#include "rdsf/candidates/candidate_finder.hpp"

#include <algorithm>
#include <cmath>

#include "rdsf/candidates/column_heights.hpp"
#include "rdsf/candidates/floor_trim.hpp"
#include "rdsf/candidates/layer_objects.hpp"
#include "rdsf/candidates/object_height.hpp"

namespace rdsf {

double iou(const cv::Rect& a, const cv::Rect& b) {
  const double inter = (a & b).area();
  const double uni = static_cast<double>(a.area()) + b.area() - inter;
  return uni > 0 ? inter / uni : 0.0;
}

namespace {

// The window's nearest-neighbour sampling, shared by both crops (so a colour crop cut later is the one
// cut_crops() would have cut): output pixel u samples source column window.x + floor((u + 0.5) * w / W),
// row v source row window.y + floor((v + 0.5) * h / H). The source columns grow with u, so those inside
// the image are the outputs inside..inside_end - 1; the others, and rows outside the image, read 0
// (black). Only the layer's pixels are kept. Depth: fill `depth`; Colour: fill `colour` from frame.bgr.
template <bool Depth, bool Colour>
void sample_window(const DepthFrame& frame, const cv::Mat1b& labels, int layer, const cv::Rect& window,
                   cv::Size crop_size, cv::Mat1w* depth, cv::Mat3b* colour) {
  if (Depth) depth->create(crop_size);
  if (Colour) colour->create(crop_size);
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
    std::uint16_t* depth_out = Depth ? depth->ptr<std::uint16_t>(v) : nullptr;
    cv::Vec3b* colour_out = Colour ? colour->ptr<cv::Vec3b>(v) : nullptr;
    const bool row_inside = y >= 0 && y < frame.depth_mm.rows;
    const int from = row_inside ? inside : crop_size.width, to = row_inside ? inside_end : crop_size.width;
    if (Depth) {
      std::fill(depth_out, depth_out + from, std::uint16_t{0});
      std::fill(depth_out + to, depth_out + crop_size.width, std::uint16_t{0});
    }
    if (Colour) {
      std::fill(colour_out, colour_out + from, black);
      std::fill(colour_out + to, colour_out + crop_size.width, black);
    }
    if (!row_inside) continue;
    const std::uint8_t* label_row = labels.ptr<std::uint8_t>(y);
    const std::uint16_t* depth_row = frame.depth_mm.ptr<std::uint16_t>(y);
    const cv::Vec3b* colour_row = Colour ? frame.bgr.ptr<cv::Vec3b>(y) : nullptr;
    for (int u = from; u < to; ++u) {
      const int x = xs[u];
      const bool in = label_row[x] == layer;
      if (Depth) depth_out[u] = in ? depth_row[x] : std::uint16_t{0};
      if (Colour) colour_out[u] = in ? colour_row[x] : black;
    }
  }
}

// `box` widened about its centre to lround(ratio * height * px_aspect) columns when narrower
// (fit.min_width_ratio, a ratio of metric width to metric height; px_aspect = fx / fy turns rows into
// columns of the same length; the caller clips it to the image); unchanged when ratio <= 0 or it is wide enough.
cv::Rect at_least_wide(cv::Rect box, double ratio, double px_aspect) {
  const int wanted = static_cast<int>(std::lround(ratio * box.height * px_aspect));
  if (ratio <= 0 || box.width >= wanted) return box;
  box.x = static_cast<int>(std::lround(box.x + box.width / 2.0 - wanted / 2.0));
  box.width = wanted;
  return box;
}

}  // namespace

void cut_crops(const DepthFrame& frame, const cv::Mat1b& labels, int layer, const cv::Rect& window,
               cv::Size crop_size, Candidate& candidate, CropColour colour) {
  if (frame.has_colour() && colour == CropColour::cut) {
    sample_window<true, true>(frame, labels, layer, window, crop_size, &candidate.depth_crop, &candidate.colour_crop);
  } else {
    candidate.colour_crop.release();
    sample_window<true, false>(frame, labels, layer, window, crop_size, &candidate.depth_crop, nullptr);
  }
}

void cut_colour_crop(const DepthFrame& frame, const cv::Mat1b& labels, Candidate& candidate) {
  if (!frame.has_colour()) {
    candidate.colour_crop.release();
    return;
  }
  sample_window<false, true>(frame, labels, candidate.layer, candidate.window_unclipped, candidate.depth_crop.size(),
                             nullptr, &candidate.colour_crop);
}

std::vector<Candidate> find_candidates(const DepthFrame& frame, const Segmentation& segmentation,
                                       const CandidateParams& params, cv::Size crop_size, CropColour colour) {
  std::vector<Candidate> candidates;
  const int layer_count = static_cast<int>(segmentation.layers.size());
  if (layer_count == 0) return candidates;
  std::vector<int> occlusion_px(static_cast<std::size_t>(layer_count) + 1, 0), hole_px(occlusion_px.size(), 0);
  for (const DepthLayer& layer : segmentation.layers) {
    const double depth_mm = std::max(1.0, layer.mean_depth_mm);
    occlusion_px[static_cast<std::size_t>(layer.label)] =
        static_cast<int>(frame.camera.rows_px(params.occlusion_gap_cm, depth_mm));
    hole_px[static_cast<std::size_t>(layer.label)] = static_cast<int>(frame.camera.rows_px(params.hole_gap_cm, depth_mm));
  }
  const auto runs = column_runs(segmentation.labels, layer_count, params.k, occlusion_px, hole_px);
  const cv::Rect image(0, 0, frame.depth_mm.cols, frame.depth_mm.rows);
  // Columns per row of the same length at the same depth: 1 for square pixels (every camera model the
  // workbench knows but a stretched frame's), so that a box half as wide as it is tall is so in metres.
  const double px_aspect = frame.camera.fx_px / frame.camera.fy_px;

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
      const int box_width = std::max(1, static_cast<int>(std::lround(box_height * px_aspect / 2.0)));
      const cv::Rect strict(object.highest - box_width / 2, top, box_width, box_height);
      candidate.strict_box = strict & image;
      const cv::Rect extent(object.fit_first, object.fit_top, object.fit_last - object.fit_first + 1,
                            bottom - object.fit_top + 1);
      candidate.extent_box = extent & image;
      candidate.fitted_box = at_least_wide(extent, params.fit.min_width_ratio, px_aspect) & image;
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
      cut_crops(frame, segmentation.labels, layer.label, candidate.window_unclipped, crop_size, candidate, colour);
      if (taller_than_a_person(candidate, frame.camera, params.max_height_cm)) continue;
      candidates.push_back(std::move(candidate));
    }
    int in_layer = 0;
    for (const LayerObject& object : found.objects) in_layer = std::max(in_layer, object.object + 1);
    objects_before += in_layer;
  }
  return candidates;
}

}  // namespace rdsf
