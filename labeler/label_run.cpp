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

#include "cli/cli.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/frame/frame_source.hpp"
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
// `added_by`: --only-added-by's option (a trial of a candidate switch), else empty.
std::string reason_of(const LabelingSession& session, const PresentedCandidate& p, const std::string& added_by) {
  char text[160];
  if (!p.frame->probabilities.empty()) {
    const double pr = p.frame->probabilities[p.index];
    const LabelingConfig& c = session.config();
    const BoostedModel& m = *session.model();
    if (c.ask == AskOrder::likely && !added_by.empty()) {
      std::snprintf(text, sizeof text, "asked: does --%s add a person? likeliest first (P = %.2f, %zu left)",
                    cli::canonical_option_name(added_by).c_str(), pr, session.pending());
    } else if (c.ask == AskOrder::likely) {
      std::snprintf(text, sizeof text, "asked: likeliest first under %s/v%d (P = %.2f, %zu left)", m.name().c_str(),
                    m.version(), pr, session.pending());
    } else if (c.ask == AskOrder::uncertain) {
      const double boundary = m.operating_probability();
      std::snprintf(text, sizeof text, "asked: uncertain under %s/v%d (|P - %.2f| = %.2f, %zu left)", m.name().c_str(),
                    m.version(), boundary, uncertainty(pr, boundary), session.pending());
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
                       const std::string& message, const std::string& added_by) {
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
    if (session.config().per_track && session.config().propagation.from_model) {
      s.model_track_labels = st.model_track_positives + st.model_track_negatives;
    }
  }
  s.reason = reason_of(session, p, added_by);
  if (!p.frame->truth_iou.empty()) s.truth_iou = p.frame->truth_iou[p.index];
  s.message = message;
  return s;
}

/// --model, checked against the set's feature spec and crops before the set is opened or created, so that
/// a wrong model changes nothing; the analyser takes the detection options it states for the options not
/// given (stated_options.hpp). Null without --model.
std::unique_ptr<BoostedModel> load_model(LabelOptions& o) {
  if (o.model.empty()) return nullptr;
  auto model = std::make_unique<BoostedModel>(BoostedModel::load(o.model, o.models_dir));
  o.session.analyser = o.given.for_model(o.session.analyser, model.get());
  const bool exists = std::filesystem::exists(std::filesystem::path(o.out_set) / "manifest.yml");
  const FeatureSpec set_spec = exists ? SampleSet::open_read(o.out_set).feature_spec() : o.session.analyser.features;
  if (!(model->feature_spec() == set_spec)) {
    fail(model->path(), "the model reads feature spec " + model->feature_spec().hash() + ", the sample set " +
                            o.out_set + (exists ? " holds " : " would hold ") + set_spec.hash() +
                            ": give a model trained on the set's features");
  }
  const std::string misfit = model_fit_problem(*model, o.session.analyser);  // crops cut the same way
  if (!misfit.empty()) fail(model->path(), misfit);
  // Said once the model is taken: a refused model's error stays the one line.
  if (const std::string stated = o.given.said_of(*model); !stated.empty()) std::cerr << "rdsf-label: " << stated << "\n";
  return model;
}

/// `analyser` with the option `name` at its default: what the candidates --only-added-by leaves out come from.
/// A usage error when it is at its default already (it would add nothing).
AnalyserParams without_option(const AnalyserParams& analyser, const std::string& name) {
  const Parameter<AnalyserParams>& row = *find_parameter(analyser_parameters(), cli::canonical_option_name(name));
  const ParameterValue fallback = row.get(AnalyserParams{});
  if (row.get(analyser) == fallback) {
    throw cli::UsageError("--only-added-by " + name + ": --" + row.name + " is at its default (" +
                          parameter_text(fallback) + ") here, so it adds no candidate");
  }
  AnalyserParams without = analyser;
  row.set(without, fallback);
  return without;
}

/// --truth with the hardly visible people marked (their candidates are asked). Null without --truth. Refused
/// when it names none of the sources' frames (every candidate would be answered "not a person").
std::unique_ptr<GroundTruth> read_truth(const LabelOptions& o) {
  if (o.truth_csv.empty()) return nullptr;
  auto truth = std::make_unique<GroundTruth>(read_ground_truth(o.truth_csv));
  std::vector<std::string> names;
  bool known = true;
  for (const std::string& spec : o.session.sources) {
    const auto frames = open_frame_source(spec, o.session.camera)->frame_names();
    if (!frames) known = false;
    if (frames) names.insert(names.end(), frames->begin(), frames->end());
  }
  const std::size_t others = o.session.sources.size() - 1;
  const std::string sources = o.session.sources.front() +
                              (others > 0 ? " and " + std::to_string(others) + " other source(s)" : std::string());
  if (known) truth_frames_not_in(*truth, o.truth_csv, names, sources);
  const std::size_t ignored = ignore_hardly_visible(*truth, o.min_visible);
  if (ignored > 0) {
    std::cerr << "rdsf-label: " << o.truth_csv << ": " << ignored << " of " << truth->people() << " people less than "
              << o.min_visible * 100 << "% visible: their candidates are asked, not answered\n";
  }
  return truth;
}

const char* const kWindow = "rdsf-label";

/// The labeling itself: presents candidates (window, --answers keys or the truth oracle), stores the answers,
/// retrains in --loop mode, and reports the counts at the end.
class Labeler {
 public:
  /// `scripted`: the --answers keys (null with a window or the truth oracle).
  Labeler(const LabelOptions& o, bool headless, SampleSetWriter& writer, const BoostedModel* model,
          const GroundTruth* truth, std::unique_ptr<gui::ScriptedKeys> scripted)
      : o_(o),
        headless_(headless),
        oracle_(o.session.truth_is_oracle),
        writer_(writer),
        session_(o.session, writer, model, truth, [this](std::int64_t frames) { scoring(frames); }),
        scripted_(std::move(scripted)) {
    if (session_.total_frames()) total_frames_ = *session_.total_frames();
  }

  /// Asks until every candidate is answered, the keys or the budget run out, or the person quits.
  void ask_all() {
    start_ = Clock::now();
    while (!quit_) {
      if (o_.budget > 0 && session_.stats().answers() >= o_.budget) {
        budget_spent_ = true;
        break;
      }
      if (o_.loop && session_.stats().answers() - answers_at_last_train_ >= o_.batch) {
        answers_at_last_train_ = session_.stats().answers();
        retrain();
        key_time_.reset();  // training time is not the key's latency
      }
      const PresentedCandidate* p = session_.current();
      if (p == nullptr) break;
      if (answers_ran_out_) {  // headless and out of keys: the rest stays unanswered, the run completes
        session_.leave_unanswered();
        continue;
      }
      char key = label_keys::kNone;
      if (next_key(*p, key)) take(key);
    }
  }

  /// The loop's end: the last model, trained on every answer, answers what it is sure about.
  void finish_loop() {
    if (!(o_.loop && session_.model() != nullptr && session_.config().model_answers)) return;
    if (session_.stats().answers() > answers_at_last_train_) retrain();
    const LabelingStats& st = session_.stats();
    if (st.positives >= o_.loop_answer_after && st.negatives >= o_.loop_answer_after) {
      const std::size_t answered = session_.finish_with_model();
      std::fprintf(stderr, "rdsf-label: loop: %s/v%d answered the %zu candidates it is sure about\n",
                   session_.model()->name().c_str(), session_.model()->version(), answered);
    } else {
      std::fprintf(stderr, "rdsf-label: loop: fewer than %ld y and %ld n answers: the model answers nothing\n",
                   o_.loop_answer_after, o_.loop_answer_after);
    }
  }

  void report(bool with_truth) const;

 private:
  // Uncertain mode: the whole session is scored first.
  void scoring(std::int64_t frames) {
    if (frames % 25 != 0 && frames != total_frames_) return;
    std::fprintf(stderr, "rdsf-label: scored %lld%s frames\n", static_cast<long long>(frames),
                 total_frames_ > 0 ? ("/" + std::to_string(total_frames_)).c_str() : "");
    if (!headless_) {
      cv::imshow(kWindow, render_note("scoring every frame first: " + std::to_string(frames) + " frames"));
      cv::waitKey(1);
    }
  }

  // The loop: every `batch` human answers, a model is trained on the set, saved and put in charge.
  void retrain();

  /// The next key: the oracle's, the script's or the person's; false when there is none to take (the
  /// script ran out, or a zoom key: the same candidate is shown again).
  bool next_key(const PresentedCandidate& p, char& key) {
    if (oracle_) {
      if (key_time_) latency_.add(*key_time_);
      key = session_.oracle_key();
    } else if (headless_) {
      if (key_time_) latency_.add(*key_time_);
      if (!scripted_->next(key)) {
        answers_ran_out_ = true;
        return false;
      }
    } else {
      key = key_from_window(p);
    }
    if (key == label_keys::kZoomIn || key == label_keys::kZoomOut) {  // the same candidate, redrawn
      zoom_ = std::clamp(key == label_keys::kZoomIn ? zoom_ * 2 : zoom_ / 2, 1.0, 8.0);
      key_time_.reset();
      return false;
    }
    return true;
  }

  char key_from_window(const PresentedCandidate& p) {
    ScreenStatus status = status_of(session_, p, start_, message_, o_.only_added_by);
    status.zoom = zoom_;
    cv::Mat3b screen = render_label_screen(p, status);
    if (o_.session.per_track) screen = add_track_strip(screen, p, session_.track_preview('y'), session_.place_preview());
    cv::imshow(kWindow, screen);
    if (key_time_) latency_.add(*key_time_);
    char key = label_keys::kNone;
    while (key == label_keys::kNone) {
      const int code = cv::waitKeyEx(100);
      if (cv::getWindowProperty(kWindow, cv::WND_PROP_VISIBLE) < 1) {
        std::cerr << "rdsf-label: window closed: every answer is saved; run again to resume\n";
        return label_keys::kQuit;
      }
      key = label_keys::from_key_code(code);
    }
    return key;
  }

  void take(char key) {
    key_time_ = Clock::now();
    message_.clear();
    if (key == label_keys::kQuit) {
      quit_ = true;
    } else if (!session_.answer(key) && key == label_keys::kUndo) {
      message_ = "nothing to undo in this session";
      key_time_.reset();
    } else if (key == label_keys::kUndo) {
      message_ = "undone: answer again";
    }
  }

  const LabelOptions& o_;
  const bool headless_, oracle_;
  SampleSetWriter& writer_;
  std::int64_t total_frames_ = 0;
  LabelingSession session_;
  std::unique_ptr<gui::ScriptedKeys> scripted_;
  std::deque<BoostedModel> loop_models_;  // every version stays alive: presented frames were scored by it
  long answers_at_last_train_ = 0;
  SampleFeatureCache features_;
  Clock::time_point start_;
  Latency latency_;
  std::optional<Clock::time_point> key_time_;
  std::string message_;
  bool quit_ = false, answers_ran_out_ = false, budget_spent_ = false;
  double zoom_ = 1.0;
};

void Labeler::retrain() {
  if (!headless_) {
    cv::imshow(kWindow, render_note("retraining on " + std::to_string(writer_.records().size()) + " samples..."));
    cv::waitKey(1);
  }
  const auto t0 = Clock::now();
  std::optional<BoostedModel> trained =
      train_loop_model(SampleSet::open_read(o_.out_set), LoopTrainingParams{}, o_.loop_model, &features_);
  const LabelingStats& st = session_.stats();
  if (!trained) {
    std::fprintf(stderr, "rdsf-label: loop: %ld answers; too few of a class to train yet\n", st.answers());
    return;
  }
  save_new_model_version(*trained, o_.loop_model, o_.models_dir);
  loop_models_.push_back(std::move(*trained));
  const BoostedModel& m = loop_models_.back();
  session_.rescore(m, /*may_answer=*/false);  // the loop's model answers wait for its end (the best model)
  const RocSummary& v = m.training().validation.summary;
  std::fprintf(stderr,
               "rdsf-label: loop: %ld answers (%ld y, %ld n), by model %ld y %ld n; %s/v%d trained on %zu samples in "
               "%.1f s: held-out AUC %.3f, TAR at FAR 1%% %.3f; %zu candidates left, the model sure of %zu\n",
               st.answers(), st.positives, st.negatives, st.model_positives, st.model_negatives, m.name().c_str(),
               m.version(), writer_.records().size(), std::chrono::duration<double>(Clock::now() - t0).count(), v.auc,
               v.tar_at_far_1, session_.pending(), session_.sure_count());
}

void Labeler::report(bool with_truth) const {
  const LabelingStats& st = session_.stats();
  std::fprintf(stderr,
               "rdsf-label: %lld frames; answered %ld (positives %ld, not people %ld of which stored %ld, skipped %ld, "
               "undone %ld); assisted: %ld positives, %ld negatives; by model: %ld positives, %ld negatives; "
               "%ld answered before; %ld left unanswered%s\n",
               static_cast<long long>(st.frames_loaded), st.answers(), st.positives, st.negatives, st.rejected,
               st.skipped, st.undone, st.auto_positives, st.auto_negatives, st.model_positives, st.model_negatives,
               st.already_answered,
               st.unanswered + (quit_ || budget_spent_ ? static_cast<long>(session_.pending_in_frame()) : 0L),
               budget_spent_ ? " (budget of answers spent: run again to resume)"
                             : quit_ ? " (quit: run again to resume)" : "");
  if (!o_.only_added_by.empty()) {
    std::fprintf(stderr, "rdsf-label: only what --%s adds: %ld candidates left out (made without it too)\n",
                 cli::canonical_option_name(o_.only_added_by).c_str(), st.not_added);
  }
  if (o_.session.truth_is_oracle && session_.model() != nullptr) {
    const long by_model = st.model_positives + st.model_negatives;
    std::fprintf(stderr, "rdsf-label: truth oracle: %ld of %ld model answers wrong (%.2f%%), %ld in the truth's uncertain band\n",
                 st.model_wrong, by_model, by_model ? 100.0 * static_cast<double>(st.model_wrong) / static_cast<double>(by_model) : 0.0,
                 st.model_in_band);
  }
  if (o_.session.per_track) {
    const long propagated = st.propagated_positives + st.propagated_negatives;
    std::fprintf(stderr, "rdsf-label: per track: %ld labels propagated (%ld y, %ld n), %ld skips", propagated,
                 st.propagated_positives, st.propagated_negatives, st.propagated_skips);
    if (with_truth) {
      std::fprintf(stderr, "; the truth contradicts %ld (%.2f%%), %ld in its uncertain band", st.propagated_wrong,
                   propagated ? 100.0 * static_cast<double>(st.propagated_wrong) / static_cast<double>(propagated) : 0.0,
                   st.propagated_in_band);
    }
    std::fprintf(stderr, "\n");
    if (o_.session.propagation.per_place) {  // a part of the line above: the labels an n gave at its place
      std::fprintf(stderr, "rdsf-label: per place: %ld of those n labels at the answer's place beyond its track",
                   st.placed_negatives);
      if (with_truth) {
        std::fprintf(stderr, "; the truth contradicts %ld (%.2f%%), %ld in its uncertain band", st.placed_wrong,
                     st.placed_negatives ? 100.0 * static_cast<double>(st.placed_wrong) / static_cast<double>(st.placed_negatives) : 0.0,
                     st.placed_in_band);
      }
      std::fprintf(stderr, "\n");
    }
    if (o_.session.propagation.from_model) {  // not in the lines above: labels no person's answer gave
      const long by_model_track = st.model_track_positives + st.model_track_negatives;
      std::fprintf(stderr, "rdsf-label: model answers' tracks: %ld labels propagated (%ld y, %ld n)", by_model_track,
                   st.model_track_positives, st.model_track_negatives);
      if (with_truth) {
        std::fprintf(stderr, "; the truth contradicts %ld (%.2f%%), %ld in its uncertain band", st.model_track_wrong,
                     by_model_track ? 100.0 * static_cast<double>(st.model_track_wrong) / static_cast<double>(by_model_track) : 0.0,
                     st.model_track_in_band);
      }
      std::fprintf(stderr, "\n");
    }
  }
  std::fprintf(stderr, "rdsf-label: %s\n", latency_.summary().c_str());
  std::fprintf(stderr, "rdsf-label: sample set %s now holds %zu samples\n", o_.out_set.c_str(), writer_.records().size());
}

}  // namespace

void check_options(const LabelOptions& o) {
  const LabelingConfig& s = o.session;
  if (!(s.reject_probability >= 0 && s.reject_probability <= s.accept_probability && s.accept_probability <= 1)) {
    std::ostringstream text;
    text << "--accept " << s.accept_probability << " must be at least --reject " << s.reject_probability
         << ", both between 0 and 1";
    throw cli::UsageError(text.str());
  }
  if (s.truth_is_oracle && o.truth_csv.empty()) throw cli::UsageError("--truth-oracle needs --truth");
  if (o.loop && o.batch < 1) throw cli::UsageError("--batch must be at least 1");
  if (reads_whole_session(s.ask) && o.model.empty() && !o.loop) {
    throw cli::UsageError(std::string("--ask ") + (s.ask == AskOrder::likely ? "likely" : "uncertain") + " needs --model");
  }
  if (s.per_track && !reads_whole_session(s.ask)) throw cli::UsageError("--per-track needs --ask uncertain or likely (or --loop)");
  if (!o.only_added_by.empty() && find_parameter(analyser_parameters(), cli::canonical_option_name(o.only_added_by)) == nullptr) {
    throw cli::UsageError("--only-added-by " + o.only_added_by + ": not a candidate or segmentation option");
  }
  if (o.budget < 0) throw cli::UsageError("--budget must be 0 (no limit) or more");
}

int run_label(const LabelOptions& options) {
  LabelOptions o = options;
  const bool headless = !o.answers.empty() || o.session.truth_is_oracle;
  if (!headless) gui::require_display("rdsf-label", "label on this machine with --answers FILE (or - for stdin) instead");
  const std::unique_ptr<BoostedModel> model = load_model(o);
  if (!o.only_added_by.empty()) o.session.only_added_beyond = without_option(o.session.analyser, o.only_added_by);
  const std::unique_ptr<GroundTruth> truth = read_truth(o);
  std::unique_ptr<gui::ScriptedKeys> scripted;
  if (headless && !o.session.truth_is_oracle) {
    scripted = std::make_unique<gui::ScriptedKeys>(
        o.answers, label_keys::from_token,
        [](char c) { return label_keys::from_key_code(static_cast<unsigned char>(c)); }, "y n s u q");
  }
  SampleSetWriter writer = SampleSetWriter::open_or_create(o.out_set, o.session.analyser.features, o.session.camera,
                                                           "rdsf-label", crop_provenance(o.session.analyser.candidates),
                                                           stated_options(o.session.analyser));
  for (const std::string& repair : writer.repairs()) {  // what a crash left: torn rows, orphan or unusable crops
    std::cerr << "rdsf-label: " << writer.dir() << ": repaired " << repair << "\n";
  }
  // No toolbar or status bar of Qt's: the picture is the whole window, keys go straight to the labeler.
  if (!headless) cv::namedWindow(kWindow, cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL);
  Labeler labeler(o, headless, writer, model.get(), truth.get(), std::move(scripted));
  labeler.ask_all();
  labeler.finish_loop();
  if (!headless) cv::destroyAllWindows();
  labeler.report(truth != nullptr);
  return 0;
}

}  // namespace rdsf
