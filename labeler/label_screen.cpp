#include "label_screen.hpp"

#include <algorithm>
#include <cstdio>

#include <opencv2/imgproc.hpp>

#include "gui/screen_text.hpp"
#include "gui/track_strip.hpp"
#include "rdsf/analysis/overlay.hpp"
#include "label_keys.hpp"

namespace rdsf {
namespace {

using namespace gui;  // the screens' colours and put()

}  // namespace

cv::Mat3b render_note(const std::string& text) {
  cv::Mat3b note(120, 640, cv::Vec3b(38, 34, 30));
  put(note, text, {16, 64}, 0.6, kText);
  return note;
}

cv::Mat3b zoom_around(const cv::Mat3b& view, const cv::Rect& box, double zoom) {
  // The part of the frame 1/zoom its size, centred on the box as far as the frame allows, enlarged back.
  const int w = std::max(1, static_cast<int>(view.cols / zoom)), h = std::max(1, static_cast<int>(view.rows / zoom));
  const cv::Point centre(box.x + box.width / 2, box.y + box.height / 2);
  const int x = std::clamp(centre.x - w / 2, 0, view.cols - w), y = std::clamp(centre.y - h / 2, 0, view.rows - h);
  cv::Mat3b out;
  cv::resize(view(cv::Rect(x, y, w, h)), out, view.size(), 0, 0, cv::INTER_NEAREST);
  return out;
}

cv::Mat3b render_label_screen(const PresentedCandidate& p, const ScreenStatus& s) {
  // Fits a 1280-pixel-wide screen: 640 frame + two crops at 2.5x (160x320) + margins = 1056 pixels. A
  // narrower frame (512x424, 320x240) keeps the 640 pixels' place, so that the status lines and the keys fit.
  constexpr int kMargin = 16, kStatusHeight = 92, kMinFrameAreaPx = 640;
  constexpr double kCropScale = 2.5;
  const LoadedFrame& loaded = *p.frame;
  const DepthFrame& frame = loaded.frame;
  const Candidate& candidate = p.candidate();
  const int crop_w = static_cast<int>(candidate.depth_crop.cols * kCropScale);
  const int crop_h = static_cast<int>(candidate.depth_crop.rows * kCropScale);
  const int panel_w = crop_w * 2 + kMargin;
  char text_zoom[32];
  const int frame_area_w = std::max(frame.width_px(), kMinFrameAreaPx);
  cv::Mat3b canvas(std::max(frame.height_px(), crop_h + 30) + kMargin * 2 + kStatusHeight,
                   frame_area_w + panel_w + kMargin * 3, cv::Vec3b(38, 34, 30));
  canvas.setTo(kBackground);

  // The frame with every candidate faint and this one highlighted.
  cv::Mat3b view = frame.has_colour() ? frame.bgr.clone() : colourise_depth(frame.depth_mm);
  for (std::size_t i = 0; i < loaded.analysis.candidates.size(); ++i) {
    if (i != p.index) cv::rectangle(view, loaded.analysis.candidates[i].strict_box, cv::Scalar(190, 190, 190), 1);
  }
  cv::rectangle(view, candidate.window, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
  cv::rectangle(view, candidate.strict_box, kHighlight, 3, cv::LINE_AA);
  // Zoomed no further than keeps the candidate's window whole.
  const double zoom = std::max(1.0, std::min({s.zoom, static_cast<double>(view.cols) / candidate.window.width,
                                              static_cast<double>(view.rows) / candidate.window.height}));
  if (zoom > 1.0) view = zoom_around(view, candidate.window, zoom);
  view.copyTo(canvas(cv::Rect(kMargin, kMargin, view.cols, view.rows)));
  if (zoom > 1.0) {
    std::snprintf(text_zoom, sizeof text_zoom, "zoom %.1fx", zoom);
    put(canvas, text_zoom, {kMargin + 8, kMargin + 22}, 0.6, kHighlight, 2);
  }

  // The crops, enlarged: depth as the classifier sees it (colourised, black = no reading / other layer).
  const int panel_x = frame_area_w + kMargin * 2;
  cv::Mat3b depth_crop = colourise_depth(candidate.depth_crop);
  cv::resize(depth_crop, depth_crop, {crop_w, crop_h}, 0, 0, cv::INTER_NEAREST);
  depth_crop.copyTo(canvas(cv::Rect(panel_x, kMargin + 22, crop_w, crop_h)));
  put(canvas, "depth crop (64x128)", {panel_x, kMargin + 14}, 0.45, kDim);
  if (!candidate.colour_crop.empty()) {
    cv::Mat3b colour_crop;
    cv::resize(candidate.colour_crop, colour_crop, {crop_w, crop_h}, 0, 0, cv::INTER_NEAREST);
    colour_crop.copyTo(canvas(cv::Rect(panel_x + crop_w + kMargin, kMargin + 22, crop_w, crop_h)));
    put(canvas, "colour crop", {panel_x + crop_w + kMargin, kMargin + 14}, 0.45, kDim);
  }
  char text[256];
  std::snprintf(text, sizeof text, "%.2f m away, %.0f cm tall", candidate.layer_depth_mm / 1000.0, candidate.height_cm);
  put(canvas, text, {panel_x, kMargin + 22 + crop_h + 24}, 0.5, kText);

  // Status and keys.
  const int status_y = canvas.rows - kStatusHeight;
  cv::line(canvas, {0, status_y}, {canvas.cols, status_y}, cv::Scalar(80, 80, 80), 1);
  std::string frames = std::to_string(s.frame_ordinal);
  if (s.total_frames) frames += "/" + std::to_string(*s.total_frames);
  std::snprintf(text, sizeof text, "frame %s (%s)   candidate %zu/%zu   positives %ld   negatives %ld   %.0f/min",
                frames.c_str(), frame.name.c_str(), s.candidate, s.candidates, s.positives, s.negatives,
                s.rate_per_minute);
  std::string first = text;
  if (s.model_positives) {
    std::snprintf(text, sizeof text, "   by model: %ld y, %ld n", *s.model_positives, *s.model_negatives);
    first += text;
    if (s.model_track_labels) {
      std::snprintf(text, sizeof text, " +%ld on tracks", *s.model_track_labels);
      first += text;
    }
  }
  put(canvas, first, {kMargin, status_y + 28}, 0.5, kText);
  std::string extra = s.reason;
  if (s.score) {
    if (s.probability) {
      std::snprintf(text, sizeof text, "%sH(x) = %.2f, P(person) = %.2f", extra.empty() ? "" : "   ", *s.score, *s.probability);
    } else {
      std::snprintf(text, sizeof text, "%smodel score H(x) = %.2f", extra.empty() ? "" : "   ", *s.score);
    }
    extra += text;
  }
  if (s.truth_iou) {
    std::snprintf(text, sizeof text, "%sIoU with ground truth %.2f (uncertain)", extra.empty() ? "" : "   ", *s.truth_iou);
    extra += text;
  }
  if (!s.message.empty()) extra += (extra.empty() ? "" : "   ") + s.message;
  if (!extra.empty()) put(canvas, extra, {kMargin, status_y + 54}, 0.55, kHighlight);
  put(canvas, label_keys::legend(), {kMargin, status_y + 80}, 0.55, kDim);
  return canvas;
}

cv::Mat3b add_track_strip(const cv::Mat3b& screen, const PresentedCandidate& asked,
                          const std::vector<PresentedCandidate>& track, const std::vector<PresentedCandidate>& place) {
  if (track.empty() && place.empty()) return screen;
  cv::Mat3b out = screen;
  if (!track.empty()) {
    std::vector<gui::StripCrop> crops;
    std::size_t asked_at = 0;
    bool placed = false;
    for (const PresentedCandidate& t : track) {
      if (!placed && t.frame->ordinal > asked.frame->ordinal) {
        asked_at = crops.size();
        crops.push_back({asked.candidate().depth_crop, asked.frame->frame.name});
        placed = true;
      }
      crops.push_back({t.candidate().depth_crop, t.frame->frame.name});
    }
    if (!placed) {
      asked_at = crops.size();
      crops.push_back({asked.candidate().depth_crop, asked.frame->frame.name});
    }
    char title[200];
    std::snprintf(title, sizeof title, "track: %zu candidates in frames %s .. %s   y: all are this person   n: none is",
                  crops.size(), crops.front().frame.c_str(), crops.back().frame.c_str());
    cv::vconcat(out, gui::render_track_strip(crops, asked_at, title, screen.cols), out);
  }
  if (!place.empty()) {  // an n labels these too; none of them is the asked one
    std::vector<gui::StripCrop> crops;
    for (const PresentedCandidate& c : place) crops.push_back({c.candidate().depth_crop, c.frame->frame.name});
    char title[200];
    std::snprintf(title, sizeof title, "same place: %zu more in frames %s .. %s   n: none of these is a person either",
                  crops.size(), crops.front().frame.c_str(), crops.back().frame.c_str());
    cv::vconcat(out, gui::render_track_strip(crops, crops.size(), title, screen.cols), out);
  }
  return out;
}

}  // namespace rdsf
