#include "review_run.hpp"

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include <opencv2/highgui.hpp>

#include "gui/display.hpp"
#include "gui/scripted_keys.hpp"
#include "review_keys.hpp"
#include "review_screen.hpp"

namespace rdsf {

namespace {

const char* kWindow = "rdsf-review";

ReviewConfig review_config(const ReviewOptions& o, bool have_model) {
  ReviewConfig config;
  config.order = parse_review_order(o.sort.empty() ? (have_model || o.folds >= 2 ? "suspicion" : "origin") : o.sort);
  config.folds = o.folds;
  config.columns = o.columns;
  config.rows = o.rows;
  return config;
}

/// What opening the set mended: repaired files and flips a killed review left half done.
void report_repairs(const ReviewSession& session, const std::string& set) {
  for (const std::string& repair : session.repairs()) std::fprintf(stderr, "rdsf-review: %s: repaired %s\n", set.c_str(), repair.c_str());
  if (session.stats().finished_flips > 0) {
    std::fprintf(stderr, "rdsf-review: %s: finished %ld flip(s) a killed review left half done\n", set.c_str(),
                 session.stats().finished_flips);
  }
}

/// --list N: the first N samples of the order (position, id, label, P, origin) on stdout.
void print_list(const ReviewSession& session, long count) {
  for (std::size_t i = 0; i < session.items().size() && static_cast<long>(i) < count; ++i) {
    const ReviewItem& item = session.items()[i];
    std::printf("%zu\tsample %lld\tlabel %d\tP %s\t%s\n", i + 1, static_cast<long long>(item.record.id),
                item.record.label, item.probability ? std::to_string(*item.probability).c_str() : "-",
                item.record.origin.c_str());
  }
  std::fflush(stdout);
}

/// The next key: from the --keys script, or from the window (which shows the session and `message`; closing
/// it is quit). False when the script has no more keys.
bool next_key(gui::ScriptedKeys* scripted, const ReviewSession& session, const std::string& message, char& key) {
  key = review_keys::kNone;
  if (scripted) return scripted->next(key);
  cv::imshow(kWindow, render_review_screen(session, message));
  while (key == review_keys::kNone) {
    const int code = cv::waitKeyEx(100);
    if (cv::getWindowProperty(kWindow, cv::WND_PROP_VISIBLE) < 1) {
      key = review_keys::kQuit;
      break;
    }
    if (code >= 0) key = review_keys::from_key_code(code);
  }
  return true;
}

/// Opens the selected sample's frame: in a window, or as a line on stdout when headless. The message for
/// the screen, empty when all went well.
std::string open_frame(const ReviewSession& session, bool headless) {
  if (session.items().empty()) return "";
  const SampleRecord& r = session.items()[session.selected()].record;
  const std::optional<DepthFrame> frame = session.frame_of(session.selected());
  if (!frame) return "frame " + r.frame + " of " + r.source + " is not there any more";
  if (headless) {
    std::printf("sample %lld: frame %s of %s, box %d,%d %dx%d\n", static_cast<long long>(r.id), r.frame.c_str(),
                r.source.c_str(), r.strict_box.x, r.strict_box.y, r.strict_box.width, r.strict_box.height);
  } else {
    cv::imshow("rdsf-review frame", render_sample_frame(*frame, r));
  }
  return "";
}

/// Does what `key` asks of the session; returns the message for the screen.
std::string apply_key(ReviewSession& session, char key, int columns, bool headless) {
  switch (key) {
    case review_keys::kFlip: return session.flip() ? "flipped: saved" : "retracted samples cannot be flipped";
    case review_keys::kRetract: return session.retract() ? "retracted: saved" : "retracted already";
    case review_keys::kNext: session.move(1); break;
    case review_keys::kPrevious: session.move(-1); break;
    case review_keys::kDown: session.move(columns); break;
    case review_keys::kUp: session.move(-columns); break;
    case review_keys::kNextPage: session.turn_page(1); break;
    case review_keys::kPreviousPage: session.turn_page(-1); break;
    case review_keys::kOpenFrame: return open_frame(session, headless);
    default: break;
  }
  return "";
}

const char* order_words(ReviewOrder order) {
  switch (order) {
    case ReviewOrder::suspicion: return "most suspicious first";
    case ReviewOrder::origin: return "by origin";
    case ReviewOrder::source: break;
  }
  return "by source";
}

}  // namespace

int run_review(const ReviewOptions& o) {
  const bool headless = !o.keys.empty();
  if (!headless) gui::require_display("rdsf-review", "review on this machine with --keys FILE (or - for stdin) instead");
  std::unique_ptr<BoostedModel> model;
  if (!o.model.empty()) model = std::make_unique<BoostedModel>(BoostedModel::load(o.model, o.models_dir));
  const ReviewConfig config = review_config(o, model != nullptr);
  std::unique_ptr<gui::ScriptedKeys> scripted;
  if (headless) {
    scripted = std::make_unique<gui::ScriptedKeys>(
        o.keys, review_keys::from_token, [](char c) { return review_keys::from_key_code(static_cast<unsigned char>(c)); },
        "f x o h j k l n p q");
  }
  ReviewSession session(o.set, model.get(), config);
  report_repairs(session, o.set);
  print_list(session, o.list);
  if (!headless) cv::namedWindow(kWindow, cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL);
  std::string message;
  char key = review_keys::kNone;
  while (next_key(scripted.get(), session, message, key) && key != review_keys::kQuit) {
    message = apply_key(session, key, config.columns, headless);
    if (headless && !message.empty() && message.find("saved") == std::string::npos) {
      std::fprintf(stderr, "rdsf-review: %s\n", message.c_str());
    }
  }
  if (!headless) cv::destroyAllWindows();
  std::fprintf(stderr, "rdsf-review: %s: %zu samples reviewed (%s); flipped %ld, retracted %ld\n", o.set.c_str(),
               session.items().size(), order_words(config.order), session.stats().flips, session.stats().retractions);
  return 0;
}

}  // namespace rdsf
