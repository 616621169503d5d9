#include "review_screen.hpp"

#include <cstdio>

#include <opencv2/imgproc.hpp>

#include "gui/screen_text.hpp"
#include "rdsf/analysis/overlay.hpp"
#include "review_keys.hpp"

namespace rdsf {
namespace {

using namespace gui;  // the screens' colours and put()
const cv::Scalar kPerson(90, 200, 90);
const cv::Scalar kNotPerson(80, 80, 230);

}  // namespace

cv::Mat3b render_review_screen(const ReviewSession& session, const std::string& message) {
  // A cell: depth and colour crop at 1.5x (96x192 each), two lines of text below. 6 columns fit 1280 px.
  constexpr int kMargin = 12, kCropW = 96, kCropH = 192, kText1 = 18, kText2 = 36, kStatus = 70;
  constexpr int kCellW = kCropW * 2 + 4 + kMargin, kCellH = kCropH + kText2 + 10 + kMargin;
  const ReviewConfig& c = session.config();
  cv::Mat3b canvas(kMargin + c.rows * kCellH + kStatus, kMargin + c.columns * kCellW, cv::Vec3b(38, 34, 30));
  canvas.setTo(kBackground);
  const std::size_t first = session.page() * session.per_page();
  char text[256];
  for (std::size_t k = 0; k < session.per_page() && first + k < session.items().size(); ++k) {
    const std::size_t i = first + k;
    const ReviewItem& item = session.items()[i];
    const int x = kMargin + static_cast<int>(k % static_cast<std::size_t>(c.columns)) * kCellW;
    const int y = kMargin + static_cast<int>(k / static_cast<std::size_t>(c.columns)) * kCellH;
    cv::Mat3b depth = colourise_depth(item.depth_crop);
    cv::resize(depth, depth, {kCropW, kCropH}, 0, 0, cv::INTER_NEAREST);
    depth.copyTo(canvas(cv::Rect(x, y, kCropW, kCropH)));
    const cv::Mat3b colour_crop = session.colour_crop(i);
    if (!colour_crop.empty()) {
      cv::Mat3b colour;
      cv::resize(colour_crop, colour, {kCropW, kCropH}, 0, 0, cv::INTER_AREA);
      colour.copyTo(canvas(cv::Rect(x + kCropW + 4, y, kCropW, kCropH)));
    }
    const bool person = item.record.label == 1;
    std::snprintf(text, sizeof text, "%s%s", person ? "person" : "not a person",
                  item.state == ReviewItem::State::flipped ? " (flipped)" : "");
    put(canvas, text, {x, y + kCropH + kText1}, 0.45, person ? kPerson : kNotPerson, 1);
    if (item.probability) {
      std::snprintf(text, sizeof text, "P %.2f  #%lld  %s", *item.probability, static_cast<long long>(item.record.id),
                    item.record.origin.c_str());
    } else {
      std::snprintf(text, sizeof text, "#%lld  %s", static_cast<long long>(item.record.id), item.record.origin.c_str());
    }
    put(canvas, text, {x, y + kCropH + kText2}, 0.4, kDim);
    if (item.state == ReviewItem::State::retracted) {
      cv::Mat3b cell = canvas(cv::Rect(x, y, kCropW * 2 + 4, kCropH));
      cell = cell * 0.3;
      put(canvas, "retracted", {x + 40, y + kCropH / 2}, 0.7, kText, 2);
    }
    if (i == session.selected()) {
      cv::rectangle(canvas, cv::Rect(x - 4, y - 4, kCropW * 2 + 12, kCropH + kText2 + 10), kHighlight, 3);
    }
  }
  const int status_y = canvas.rows - kStatus;
  cv::line(canvas, {0, status_y}, {canvas.cols, status_y}, cv::Scalar(80, 80, 80), 1);
  const char* order = c.order == ReviewOrder::suspicion ? "most suspicious first"
                      : c.order == ReviewOrder::origin  ? "by origin"
                                                        : "by source";
  std::snprintf(text, sizeof text, "page %zu/%zu   sample %zu/%zu   %s   flipped %ld   retracted %ld%s%s",
                session.pages() ? session.page() + 1 : 0, session.pages(), session.items().empty() ? 0 : session.selected() + 1,
                session.items().size(), order, session.stats().flips, session.stats().retractions,
                message.empty() ? "" : "   ", message.c_str());
  put(canvas, text, {kMargin, status_y + 26}, 0.5, kText);
  put(canvas, review_keys::legend(), {kMargin, status_y + 54}, 0.5, kDim);
  return canvas;
}

cv::Mat3b render_sample_frame(const DepthFrame& frame, const SampleRecord& record) {
  cv::Mat3b view = frame.has_colour() ? frame.bgr.clone() : colourise_depth(frame.depth_mm);
  cv::rectangle(view, record.window, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
  cv::rectangle(view, record.strict_box, kHighlight, 3, cv::LINE_AA);
  put(view, frame.name + "  #" + std::to_string(record.id), {10, 24}, 0.6, kHighlight, 2);
  return view;
}

}  // namespace rdsf
