#include "label_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

#include <opencv2/highgui.hpp>

#include "rdsf/core/error.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/pipeline/model_fit.hpp"
#include "rdsf/labeling/active_learning.hpp"
#include "gui/display.hpp"
#include "gui/scripted_keys.hpp"
#include "label_keys.hpp"
#include "label_screen.hpp"

namespace rdsf {
namespace {

using Clock = std::chrono::steady_clock;

struct Latency {
  std::vector<double> ms;
  void add(Clock::time_point since) { ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - since).count()); }
  std::string summary() const {
    if (ms.empty()) return "no candidate followed a key";
    std::vector<double> sorted = ms;
    std::sort(sorted.begin(), sorted.end());
    double sum = 0;
    for (double v : sorted) sum += v;
    char text[160];
    std::snprintf(text, sizeof text, "key to next candidate: mean %.1f ms, 95%% %.1f ms, max %.1f ms over %zu keys",
                  sum / static_cast<double>(sorted.size()), sorted[sorted.size() * 95 / 100], sorted.back(),
                  sorted.size());
    return text;
  }
};

// Why a candidate is shown: the person's time is spent here because neither truth nor model is sure.
std::string reason_of(const LabelingSession& session, const PresentedCandidate& p) {
  char text[160];
  if (!p.frame->probabilities.empty()) {
    const double pr = p.frame->probabilities[p.index];
    const LabelingConfig& c = session.config();
    const BoostedModel& m = *session.model();
    if (c.ask == AskOrder::uncertain) {
      std::snprintf(text, sizeof text, "asked: uncertain under %s/v%d (|P - 0.5| = %.2f, %zu left)", m.name().c_str(),
                    m.version(), std::abs(pr - 0.5), session.pending());
    } else if (c.model_answers) {
      std::snprintf(text, sizeof text, "asked: model unsure (%.2f < P < %.2f)", c.reject_probability,
                    c.accept_probability);
    } else {
      return "";
    }
    return text;
  }
  return "";
}

ScreenStatus status_of(LabelingSession& session, const PresentedCandidate& p, Clock::time_point start,
                       const std::string& message) {
  const LabelingStats& st = session.stats();
  ScreenStatus s;
  s.frame_ordinal = p.frame->ordinal;
  s.total_frames = session.total_frames();
  s.candidate = p.index + 1;
  s.candidates = p.frame->analysis.candidates.size();
  s.positives = st.positives + st.auto_positives;
  s.negatives = st.negatives + st.auto_negatives;
  const double minutes = std::chrono::duration<double>(Clock::now() - start).count() / 60.0;
  s.rate_per_minute = minutes > 0 ? static_cast<double>(st.answers()) / minutes : 0.0;
  if (!p.frame->scores.empty()) s.score = p.frame->scores[p.index];
  if (!p.frame->probabilities.empty()) s.probability = p.frame->probabilities[p.index];
  if (session.model() != nullptr && session.config().model_answers) {
    s.model_positives = st.model_positives;
    s.model_negatives = st.model_negatives;
  }
  s.reason = reason_of(session, p);
  if (!p.frame->truth_iou.empty()) s.truth_iou = p.frame->truth_iou[p.index];
  s.message = message;
  return s;
}

}  // namespace

int run_label(const LabelOptions& o) {
  const bool oracle = o.session.truth_is_oracle;
  const bool headless = !o.answers.empty() || oracle;
  if (!headless) {
    gui::require_display("rdsf-label", "label on this machine with --answers FILE (or - for stdin) instead");
  }
  std::unique_ptr<BoostedModel> model;
  if (!o.model.empty()) {
    model = std::make_unique<BoostedModel>(BoostedModel::load(o.model, o.models_dir));
    // Checked before the set is opened or created, so that a wrong model changes nothing.
    const bool exists = std::filesystem::exists(std::filesystem::path(o.out_set) / "manifest.yml");
    const FeatureSpec set_spec = exists ? SampleSet::open_read(o.out_set).feature_spec() : o.session.analyser.features;
    if (!(model->feature_spec() == set_spec)) {
      fail(model->path(), "the model reads feature spec " + model->feature_spec().hash() + ", the sample set " +
                              o.out_set + (exists ? " holds " : " would hold ") + set_spec.hash() +
                              ": give a model trained on the set's features");
    }
    const std::string misfit = model_fit_problem(*model, o.session.analyser);  // crops cut the same way
    if (!misfit.empty()) fail(model->path(), misfit);
  }
  std::unique_ptr<GroundTruth> truth;
  if (!o.truth_csv.empty()) {
    truth = std::make_unique<GroundTruth>(read_ground_truth(o.truth_csv));
    const std::size_t ignored = ignore_hardly_visible(*truth, o.min_visible);
    if (ignored > 0) {
      std::cerr << "rdsf-label: " << o.truth_csv << ": " << ignored << " of " << truth->people() << " people less than "
                << o.min_visible * 100 << "% visible: their candidates are asked, not answered\n";
    }
  }
  std::unique_ptr<gui::ScriptedKeys> scripted;
  if (headless && !oracle) {
    scripted = std::make_unique<gui::ScriptedKeys>(
        o.answers, label_keys::from_token,
        [](char c) { return label_keys::from_key_code(static_cast<unsigned char>(c)); }, "y n s u q");
  }

  SampleSetWriter writer = SampleSetWriter::open_or_create(o.out_set, o.session.analyser.features, o.session.camera,
                                                           "rdsf-label", crop_provenance(o.session.analyser.candidates));
  for (const std::string& repair : writer.repairs()) {  // what a crash left: torn rows, orphan or unusable crops
    std::cerr << "rdsf-label: " << writer.dir() << ": repaired " << repair << "\n";
  }
  const char* window = "rdsf-label";
  // No toolbar or status bar of Qt's: the picture is the whole window, keys go straight to the labeler.
  if (!headless) cv::namedWindow(window, cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL);
  std::int64_t total_frames = 0;
  auto scoring = [&](std::int64_t frames) {  // uncertain mode: the whole session is scored first
    if (frames % 25 != 0 && frames != total_frames) return;
    std::fprintf(stderr, "rdsf-label: scored %lld%s frames\n", static_cast<long long>(frames),
                 total_frames > 0 ? ("/" + std::to_string(total_frames)).c_str() : "");
    if (!headless) {
      cv::imshow(window, render_note("scoring every frame first: " + std::to_string(frames) + " frames"));
      cv::waitKey(1);
    }
  };
  LabelingSession session(o.session, writer, model.get(), truth.get(), scoring);
  if (session.total_frames()) total_frames = *session.total_frames();

  // The loop: every `batch` human answers, a model is trained on the set, saved and put in charge.
  std::deque<BoostedModel> loop_models;  // every version stays alive: presented frames were scored by it
  long answers_at_last_train = 0;
  SampleFeatureCache features;
  auto retrain = [&] {
    if (!headless) {
      cv::imshow(window, render_note("retraining on " + std::to_string(writer.records().size()) + " samples..."));
      cv::waitKey(1);
    }
    const auto t0 = Clock::now();
    std::optional<BoostedModel> trained = train_loop_model(SampleSet::open_read(o.out_set), LoopTrainingParams{}, o.loop_model, &features);
    const LabelingStats& st = session.stats();
    if (!trained) {
      std::fprintf(stderr, "rdsf-label: loop: %ld answers; too few of a class to train yet\n", st.answers());
      return;
    }
    save_new_model_version(*trained, o.loop_model, o.models_dir);
    loop_models.push_back(std::move(*trained));
    const BoostedModel& m = loop_models.back();
    session.rescore(m, /*may_answer=*/false);  // the loop's model answers wait for its end (the best model)
    const RocSummary& v = m.training().validation.summary;
    std::fprintf(stderr,
                 "rdsf-label: loop: %ld answers (%ld y, %ld n), by model %ld y %ld n; %s/v%d trained on %zu samples in "
                 "%.1f s: held-out AUC %.3f, TAR at FAR 1%% %.3f; %zu candidates left, the model sure of %zu\n",
                 st.answers(), st.positives, st.negatives, st.model_positives, st.model_negatives, m.name().c_str(),
                 m.version(), writer.records().size(), std::chrono::duration<double>(Clock::now() - t0).count(), v.auc,
                 v.tar_at_far_1, session.pending(), session.sure_count());
  };
  const auto start = Clock::now();
  Latency latency;
  std::optional<Clock::time_point> key_time;
  std::string message;
  bool quit = false, answers_ran_out = false, budget_spent = false;
  double zoom = 1.0;
  while (!quit) {
    if (o.budget > 0 && session.stats().answers() >= o.budget) {
      budget_spent = true;
      break;
    }
    if (o.loop && session.stats().answers() - answers_at_last_train >= o.batch) {
      answers_at_last_train = session.stats().answers();
      retrain();
      key_time.reset();  // training time is not the key's latency
    }
    const PresentedCandidate* p = session.current();
    if (p == nullptr) break;
    if (answers_ran_out) {  // headless and out of keys: the rest stays unanswered, the run completes
      session.leave_unanswered();
      continue;
    }
    char key = label_keys::kNone;
    if (oracle) {
      if (key_time) latency.add(*key_time);
      key = session.oracle_key();
    } else if (headless) {
      if (key_time) latency.add(*key_time);
      if (!scripted->next(key)) {
        answers_ran_out = true;
        continue;
      }
    } else {
      ScreenStatus status = status_of(session, *p, start, message);
      status.zoom = zoom;
      cv::Mat3b screen = render_label_screen(*p, status);
      if (o.session.per_track) screen = add_track_strip(screen, *p, session.track_preview('y'));
      cv::imshow(window, screen);
      if (key_time) latency.add(*key_time);
      while (key == label_keys::kNone) {
        const int code = cv::waitKeyEx(100);
        if (cv::getWindowProperty(window, cv::WND_PROP_VISIBLE) < 1) {
          std::cerr << "rdsf-label: window closed: every answer is saved; run again to resume\n";
          key = label_keys::kQuit;
          break;
        }
        key = label_keys::from_key_code(code);
      }
    }
    if (key == label_keys::kZoomIn || key == label_keys::kZoomOut) {  // the same candidate, redrawn
      zoom = std::clamp(key == label_keys::kZoomIn ? zoom * 2 : zoom / 2, 1.0, 8.0);
      key_time.reset();
      continue;
    }
    key_time = Clock::now();
    message.clear();
    if (key == label_keys::kQuit) {
      quit = true;
    } else if (!session.answer(key) && key == label_keys::kUndo) {
      message = "nothing to undo in this session";
      key_time.reset();
    } else if (key == label_keys::kUndo) {
      message = "undone: answer again";
    }
  }
  if (o.loop && session.model() != nullptr && session.config().model_answers) {
    // The loop's end: the last model, trained on every answer, answers what it is sure about.
    if (session.stats().answers() > answers_at_last_train) retrain();
    const LabelingStats& st = session.stats();
    if (st.positives >= o.loop_answer_after && st.negatives >= o.loop_answer_after) {
      const std::size_t answered = session.finish_with_model();
      std::fprintf(stderr, "rdsf-label: loop: %s/v%d answered the %zu candidates it is sure about\n",
                   session.model()->name().c_str(), session.model()->version(), answered);
    } else {
      std::fprintf(stderr, "rdsf-label: loop: fewer than %ld y and %ld n answers: the model answers nothing\n",
                   o.loop_answer_after, o.loop_answer_after);
    }
  }
  if (!headless) cv::destroyAllWindows();

  const LabelingStats& st = session.stats();
  std::fprintf(stderr,
               "rdsf-label: %lld frames; answered %ld (positives %ld, not people %ld of which stored %ld, skipped %ld, "
               "undone %ld); assisted: %ld positives, %ld negatives; by model: %ld positives, %ld negatives; "
               "%ld answered before; %ld left unanswered%s\n",
               static_cast<long long>(st.frames_loaded), st.answers(), st.positives, st.negatives, st.rejected,
               st.skipped, st.undone, st.auto_positives, st.auto_negatives, st.model_positives, st.model_negatives,
               st.already_answered,
               st.unanswered + (quit || budget_spent ? static_cast<long>(session.pending_in_frame()) : 0L),
               budget_spent ? " (budget of answers spent: run again to resume)"
                            : quit ? " (quit: run again to resume)" : "");
  if (o.session.truth_is_oracle && session.model() != nullptr) {
    const long by_model = st.model_positives + st.model_negatives;
    std::fprintf(stderr, "rdsf-label: truth oracle: %ld of %ld model answers wrong (%.2f%%), %ld in the truth's uncertain band\n",
                 st.model_wrong, by_model, by_model ? 100.0 * static_cast<double>(st.model_wrong) / static_cast<double>(by_model) : 0.0,
                 st.model_in_band);
  }
  if (o.session.per_track) {
    const long propagated = st.propagated_positives + st.propagated_negatives;
    std::fprintf(stderr, "rdsf-label: per track: %ld labels propagated (%ld y, %ld n), %ld skips", propagated,
                 st.propagated_positives, st.propagated_negatives, st.propagated_skips);
    if (truth) {
      std::fprintf(stderr, "; the truth contradicts %ld (%.2f%%), %ld in its uncertain band", st.propagated_wrong,
                   propagated ? 100.0 * static_cast<double>(st.propagated_wrong) / static_cast<double>(propagated) : 0.0,
                   st.propagated_in_band);
    }
    std::fprintf(stderr, "\n");
  }
  std::fprintf(stderr, "rdsf-label: %s\n", latency.summary().c_str());
  std::fprintf(stderr, "rdsf-label: sample set %s now holds %zu samples\n", o.out_set.c_str(), writer.records().size());
  return 0;
}

}  // namespace rdsf
