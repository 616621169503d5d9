#include "review_run.hpp"

#include <cstdio>
#include <memory>

#include <opencv2/highgui.hpp>

#include "gui/display.hpp"
#include "gui/scripted_keys.hpp"
#include "review_keys.hpp"
#include "review_screen.hpp"

namespace rdsf {

int run_review(const ReviewOptions& o) {
  const bool headless = !o.keys.empty();
  if (!headless) gui::require_display("rdsf-review", "review on this machine with --keys FILE (or - for stdin) instead");
  std::unique_ptr<BoostedModel> model;
  if (!o.model.empty()) model = std::make_unique<BoostedModel>(BoostedModel::load(o.model, o.models_dir));
  ReviewConfig config;
  config.order = parse_review_order(o.sort.empty() ? (model || o.folds >= 2 ? "suspicion" : "origin") : o.sort);
  config.folds = o.folds;
  config.columns = o.columns;
  config.rows = o.rows;
  std::unique_ptr<gui::ScriptedKeys> scripted;
  if (headless) {
    scripted = std::make_unique<gui::ScriptedKeys>(
        o.keys, review_keys::from_token, [](char c) { return review_keys::from_key_code(static_cast<unsigned char>(c)); },
        "f x o h j k l n p q");
  }
  ReviewSession session(o.set, model.get(), config);
  for (const std::string& repair : session.repairs()) std::fprintf(stderr, "rdsf-review: %s: repaired %s\n", o.set.c_str(), repair.c_str());
  if (session.stats().finished_flips > 0) {
    std::fprintf(stderr, "rdsf-review: %s: finished %ld flip(s) a killed review left half done\n", o.set.c_str(),
                 session.stats().finished_flips);
  }
  for (std::size_t i = 0; i < session.items().size() && static_cast<long>(i) < o.list; ++i) {
    const ReviewItem& item = session.items()[i];
    std::printf("%zu\tsample %lld\tlabel %d\tP %s\t%s\n", i + 1, static_cast<long long>(item.record.id),
                item.record.label, item.probability ? std::to_string(*item.probability).c_str() : "-",
                item.record.origin.c_str());
  }
  std::fflush(stdout);
  const char* window = "rdsf-review";
  if (!headless) cv::namedWindow(window, cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL);
  std::string message;
  while (true) {
    char key = review_keys::kNone;
    if (headless) {
      if (!scripted->next(key)) break;
    } else {
      cv::imshow(window, render_review_screen(session, message));
      while (key == review_keys::kNone) {
        const int code = cv::waitKeyEx(100);
        if (cv::getWindowProperty(window, cv::WND_PROP_VISIBLE) < 1) {
          key = review_keys::kQuit;
          break;
        }
        if (code >= 0) key = review_keys::from_key_code(code);
      }
    }
    message.clear();
    if (key == review_keys::kQuit) break;
    switch (key) {
      case review_keys::kFlip:
        message = session.flip() ? "flipped: saved" : "retracted samples cannot be flipped";
        break;
      case review_keys::kRetract:
        message = session.retract() ? "retracted: saved" : "retracted already";
        break;
      case review_keys::kNext: session.move(1); break;
      case review_keys::kPrevious: session.move(-1); break;
      case review_keys::kDown: session.move(config.columns); break;
      case review_keys::kUp: session.move(-config.columns); break;
      case review_keys::kNextPage: session.turn_page(1); break;
      case review_keys::kPreviousPage: session.turn_page(-1); break;
      case review_keys::kOpenFrame: {
        if (session.items().empty()) break;
        const SampleRecord& r = session.items()[session.selected()].record;
        const std::optional<DepthFrame> frame = session.frame_of(session.selected());
        if (!frame) {
          message = "frame " + r.frame + " of " + r.source + " is not there any more";
        } else if (headless) {
          std::printf("sample %lld: frame %s of %s, box %d,%d %dx%d\n", static_cast<long long>(r.id), r.frame.c_str(),
                      r.source.c_str(), r.strict_box.x, r.strict_box.y, r.strict_box.width, r.strict_box.height);
        } else {
          cv::imshow("rdsf-review frame", render_sample_frame(*frame, r));
        }
        break;
      }
      default: break;
    }
    if (headless && !message.empty() && message.find("saved") == std::string::npos) {
      std::fprintf(stderr, "rdsf-review: %s\n", message.c_str());
    }
  }
  if (!headless) cv::destroyAllWindows();
  std::fprintf(stderr, "rdsf-review: %s: %zu samples reviewed (%s); flipped %ld, retracted %ld\n", o.set.c_str(),
               session.items().size(),
               config.order == ReviewOrder::suspicion ? "most suspicious first"
               : config.order == ReviewOrder::origin  ? "by origin"
                                                      : "by source",
               session.stats().flips, session.stats().retractions);
  return 0;
}

}  // namespace rdsf
