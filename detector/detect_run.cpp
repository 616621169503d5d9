#include "detector/detect_run.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <functional>
#include <memory>
#include <optional>
#include <thread>

#include <opencv2/highgui.hpp>

#include "cli/cli.hpp"
#include "cli/progress.hpp"
#include "rdsf/core/clock.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/thread_count.hpp"
#include "rdsf/analysis/detection_csv.hpp"
#include "rdsf/analysis/overlay.hpp"
#include "rdsf/evaluation/candidate_misses.hpp"
#include "rdsf/evaluation/ground_truth.hpp"
#include "rdsf/evaluation/threshold_sweep.hpp"
#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/frame/depth_png.hpp"
#include "rdsf/frame/depth_units.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "gui/display.hpp"
#include "rdsf/pipeline/live_pipeline.hpp"
#include "rdsf/pipeline/parallel_pipeline.hpp"
#include "rdsf/pipeline/people_overlay.hpp"
#include "rdsf/pipeline/stated_options.hpp"

namespace rdsf {
namespace {

void print_times(const StageTimes& t, std::int64_t frames, std::int64_t candidates, double wall_s) {
  const double n = static_cast<double>(std::max<std::int64_t>(1, frames));
  std::fprintf(stderr,
               "rdsf-detect: %lld frames, %.2f candidates per frame, %.1f frames/s overall\n"
               "  per frame: segmentation %.2f ms, candidates %.2f ms, features %.2f ms, classifier %.3f ms, "
               "tracking %.3f ms (system %.2f ms)\n",
               static_cast<long long>(frames), static_cast<double>(candidates) / n,
               wall_s > 0 ? static_cast<double>(frames) / wall_s : 0.0, t.segmentation_ms / n, t.candidates_ms / n,
               t.features_ms / n, t.classifier_ms / n, t.tracking_ms / n, t.total_ms() / n);
}

// People of the truth with a candidate whose box reaches IoU >= 0.5 (the reported box and the other one),
// and the people without one: what the candidates allow before any classifier is asked.
class CandidateCoverage {
 public:
  void add(const std::vector<TruthBox>& people, const std::vector<Candidate>& candidates, BoxKind box) {
    const BoxKind other = box == BoxKind::fitted ? BoxKind::strict : BoxKind::fitted;
    for (const TruthBox& person : people) {
      if (person.ignored) continue;
      double best = 0, best_other = 0;
      cv::Rect best_box;
      for (const Candidate& c : candidates) {
        const cv::Rect& reported = reported_box(c, box);
        const double overlap = iou(reported, person.box);
        if (overlap > best) best = overlap, best_box = reported;
        best_other = std::max(best_other, iou(reported_box(c, other), person.box));
      }
      ++people_;
      found_ += best >= 0.5 ? 1 : 0;
      found_other_ += best_other >= 0.5 ? 1 : 0;
      if (best < 0.5) misses_.add(miss_shape(person.box, best_box, best));
    }
  }
  std::string summary(BoxKind box) const {
    const char* name = box == BoxKind::fitted ? "fitted" : "strict";
    const char* other = box == BoxKind::fitted ? "strict" : "fitted";
    char text[256];
    std::snprintf(text, sizeof text,
                  "rdsf-detect: %lld of %lld people have a candidate (%s box IoU >= 0.5), %lld without; %s box: "
                  "%lld\n",
                  static_cast<long long>(found_), static_cast<long long>(people_), name,
                  static_cast<long long>(people_ - found_), other, static_cast<long long>(found_other_));
    std::string lines = text;
    if (misses_.total() > 0) {
      lines += "rdsf-detect: without a candidate, by the nearest candidate's " + std::string(name) +
               " box: " + misses_.summary() + " (candidate_misses.hpp)\n";
    }
    return lines;
  }

 private:
  std::int64_t people_ = 0, found_ = 0, found_other_ = 0;
  MissShapes misses_;  // the people without a candidate, by the best candidate's shape
};

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// Live mode: frames are pushed as they arrive (a device at its own rate, any other source paced at
/// --fps), analysed by LivePipeline's workers; prints arrivals, drops and the latency percentiles.
void run_live(const DetectOptions& o, PeoplePipeline& pipeline, FrameSource& source,
              const std::function<void(const DepthFrame&, const PipelineFrame&)>& handle) {
  const bool device = is_openni_spec(o.source) && !ends_with(o.source, ".oni");
  const SteadyClock clock;
  LivePipeline live(pipeline, {resolve_thread_count(o.threads)}, clock,
                    [&](const DepthFrame& f, PipelineFrame& r, std::int64_t) { handle(f, r); });
  const auto period = std::chrono::duration<double>(1.0 / o.fps);
  const auto start = std::chrono::steady_clock::now();
  DepthFrame frame;
  std::int64_t count = 0;
  while ((o.max_frames == 0 || count < o.max_frames) && source.next(frame)) {
    if (!device) {
      std::this_thread::sleep_until(start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(period * count));
    }
    live.push(std::move(frame));
    frame = DepthFrame();
    ++count;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  live.finish();
  const LiveStats s = live.stats();
  std::fprintf(stderr,
               "rdsf-detect: live: %lld frames arrived in %.2f s (%.1f frames/s%s), %lld processed, %lld dropped; "
               "latency arrival to detections p50 %.2f ms, p95 %.2f ms, p99 %.2f ms, max %.2f ms\n",
               static_cast<long long>(s.arrived), seconds, seconds > 0 ? static_cast<double>(s.arrived) / seconds : 0.0,
               device ? ", the device's rate" : ", paced by --fps", static_cast<long long>(s.processed),
               static_cast<long long>(s.dropped), s.p50_ms, s.p95_ms, s.p99_ms, s.max_ms);
}

/// Refuses to replace a report without --force and --show without a display (errors, exit 1).
void check_outputs(const DetectOptions& o) {
  if (!o.report_dir.empty() && !o.force && std::filesystem::exists(std::filesystem::path(o.report_dir) / "metrics.csv")) {
    throw Error(o.report_dir + ": already holds a report (pass --force to replace it)");
  }
  if (o.show) gui::require_display("rdsf-detect --show", "drop --show or use --save-dir to get pictures");
}

/// The pipeline's parameters for these models: the first model's stated detection options for the options
/// not given (stated_options.hpp; every further model must run with the same, as they score the same
/// candidates), and the detector computes the first model's feature spec unless --feature-spec names one
/// (then they must agree: PeoplePipeline refuses otherwise). Further models score the same crops in their
/// own specs.
PipelineParams pipeline_params_for(const DetectOptions& o, const std::vector<BoostedModel>& models) {
  PipelineParams params = o.pipeline;
  cli::apply_background(o.background, params.analyser);
  if (!models.empty()) {
    const GivenOptions& given = params.analyser_given;
    const RecordedParameters first = stated_options(given.for_model(params.analyser, &models.front()));
    for (std::size_t m = 1; m < models.size(); ++m) {
      const RecordedParameters other = stated_options(given.for_model(params.analyser, &models[m]));
      if (const std::optional<std::size_t> i = first_difference(first, other)) {  // both list every option
        throw cli::UsageError("models " + model_label(models.front()) + " and " + model_label(models[m]) +
                              " run with other detection options (" + first[*i].first + " " + first[*i].second +
                              " / " + other[*i].second +
                              "): they score the same candidates, so give that option, or evaluate them apart");
      }
    }
    params.analyser = given.for_model(params.analyser, &models.front());
  }
  if (!models.empty() && !o.feature_spec_given) params.analyser.features = models.front().feature_spec();
  // The evaluation sweeps tracking over every candidate's colour histogram, not only the detections'.
  params.colour_crops_of_all = !o.truth_csv.empty();
  return params;
}

/// --truth read, with the hardly visible people marked ignored.
GroundTruth read_truth(const DetectOptions& o) {
  GroundTruth truth = read_ground_truth(o.truth_csv);
  const std::size_t ignored = ignore_hardly_visible(truth, o.min_visible);
  std::cerr << "rdsf-detect: " << o.truth_csv << ": " << truth.people() << " people, " << ignored
            << " of them less than " << o.min_visible * 100 << "% visible (ignored: no miss, no false positive)\n";
  return truth;
}

/// The truth must name the source's frames (before anything is read or written): refused when it names none of
/// them, and the frames it names that the source does not have are counted aloud (truth_frames_not_in).
void check_truth_frames(const DetectOptions& o, const GroundTruth& truth, const FrameSource& source) {
  const auto names = source.frame_names();
  if (!names) return;  // a live device: its frames are named as they come
  const std::size_t absent = truth_frames_not_in(truth, o.truth_csv, *names, o.source);
  if (absent > 0) {
    std::cerr << "rdsf-detect: " << o.truth_csv << ": " << absent << " of its " << truth.frames.size()
              << " frames are not in " << o.source << " (not counted)\n";
  }
}

void create_save_dir(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) fail(dir, "cannot create folder: " + ec.message());
}

void announce(const DetectOptions& o, const FrameSource& source, const std::vector<BoostedModel>& models) {
  std::cerr << "rdsf-detect: " << source.description() << "; " << resolve_thread_count(o.threads)
            << (o.live ? " live worker(s)" : " thread(s)");
  for (const BoostedModel& m : models) {
    std::cerr << "; model " << model_label(m) << " (" << m.path() << "), " << o.pipeline.decision_text(m);
  }
  std::cerr << "\n";
  const std::string stated = models.empty() ? "" : o.pipeline.analyser_given.said_of(models.front());
  if (!stated.empty()) std::cerr << "rdsf-detect: " << stated << "\n";
}

/// Each frame after tracking, in frame order, one at a time (on the calling thread, or a live worker):
/// writes the CSV row, keeps what the evaluation needs, saves or shows the picture, counts.
class FrameHandler {
 public:
  FrameHandler(const DetectOptions& o, const std::vector<BoostedModel>& models, const GroundTruth& truth,
               const PeoplePipeline& pipeline, DetectionCsv* csv, std::optional<std::int64_t> frame_count)
      : evaluated(models.size()), o_(o), models_(models), truth_(truth), pipeline_(pipeline), csv_(csv),
        box_(pipeline.params().analyser.reported_box), progress_(std::cerr, "frames", frame_count) {
    for (const BoostedModel& m : models) {
      scorers_.emplace_back(m);
      mirrors_.emplace_back(m, o_.pipeline);
    }
  }

  /// false: the viewer asked to stop.
  bool operator()(const DepthFrame& frame, const PipelineFrame& processed) {
    total += processed.times;
    const auto& found = processed.analysis.candidates;
    std::vector<CandidateOutcome> outcomes;
    for (std::size_t i = 0; i < processed.scores.size(); ++i) {
      const TrackedPerson* person = pipeline_.tracker().person(processed.person[i]);
      outcomes.push_back({processed.scores[i], processed.person[i], person != nullptr ? person->distance_cm : 0.0});
      detections += processed.person[i] != 0 ? 1 : 0;
    }
    if (!units_checked_ && cv::countNonZero(frame.depth_mm) > 0) {  // once, on the first frame with readings
      units_checked_ = true;
      const std::string note = depth_units_note(frame.depth_mm);
      if (!note.empty()) progress_.note("rdsf-detect: warning: frame " + frame.name + ": " + note);
    }
    if (csv_) csv_->write_frame(frame.name, found, outcomes);
    if (!o_.truth_csv.empty()) keep_for_evaluation(frame, processed);
    const bool go_on = picture(frame, processed);
    ++frames;
    candidates += static_cast<std::int64_t>(found.size());
    progress_.update(frames, counts());
    return go_on;
  }

  void finish() { progress_.finish(frames, counts()); }

  std::int64_t frames = 0, candidates = 0, detections = 0;
  StageTimes total;
  CandidateCoverage coverage;
  std::vector<std::vector<EvaluatedFrame>> evaluated;  ///< per model, every frame's scored candidates

 private:
  std::string counts() const {
    return "candidates " + std::to_string(candidates) +
           (models_.empty() ? "" : ", detections " + std::to_string(detections));
  }

  void keep_for_evaluation(const DepthFrame& frame, const PipelineFrame& processed) {
    const auto& found = processed.analysis.candidates;
    coverage.add(truth_.in(frame.name), found, box_);
    std::vector<EvaluatedCandidate> base;
    for (std::size_t i = 0; i < found.size(); ++i) {
      base.push_back({reported_box(found[i], box_), found[i].layer_depth_mm, 0.0,
                      ColourHistogram::of(found[i].colour_crop, found[i].depth_crop, o_.pipeline.tracking.histogram_bins),
                      o_.pipeline.suppress_duplicates ? kin_of(found[i]) : CandidateKin{}});
    }
    for (std::size_t m = 0; m < models_.size(); ++m) {
      std::vector<double> scores;
      if (m == 0) {
        scores = processed.scores;
      } else {  // as the pipeline scores its model
        cv::Mat1f crop_features, mirror_features;
        scorers_[m].compute(found, crop_features, mirrors_[m].reads_mirror() ? &mirror_features : nullptr);
        scores = scorers_[m].score_rows(crop_features);
        mirrors_[m].apply(scorers_[m], found, crop_features, mirror_features, scores);
      }
      EvaluatedFrame e{frame.name, frame.index, frame.camera, base};
      for (std::size_t i = 0; i < scores.size(); ++i) e.candidates[i].score = scores[i];
      evaluated[m].push_back(std::move(e));
    }
  }

  /// Saves and/or shows the frame's picture; false when the viewer pressed q or Esc.
  bool picture(const DepthFrame& frame, const PipelineFrame& processed) {
    if (o_.save_dir.empty() && !o_.show) return true;
    const cv::Mat3b picture =
        models_.empty() ? render_candidates(frame, processed.analysis.segmentation, processed.analysis.candidates, nullptr, box_)
                        : render_people(frame, processed, pipeline_.tracker(), box_);
    if (!o_.save_dir.empty()) {
      write_png_atomically((std::filesystem::path(o_.save_dir) / (frame.name + ".detections.png")).string(), picture);
    }
    if (!o_.show) return true;
    cv::imshow("rdsf-detect", picture);
    const int key = cv::waitKey(1);
    return !(key == 'q' || key == 27);
  }

  const DetectOptions& o_;
  const std::vector<BoostedModel>& models_;
  const GroundTruth& truth_;
  const PeoplePipeline& pipeline_;
  DetectionCsv* csv_;
  BoxKind box_;
  std::vector<ModelScorer> scorers_;
  std::vector<MirrorScoring> mirrors_;  ///< per model, as the pipeline turns its crop scores into scores
  cli::Progress progress_;
  bool units_checked_ = false;  ///< depth_units_note() was asked (of the first frame with readings)
};

/// Runs every frame through the pipeline (live or in frame order) into the handler; the wall time in s.
double process_frames(const DetectOptions& o, PeoplePipeline& pipeline, FrameSource& source, FrameHandler& handler) {
  const auto start = std::chrono::steady_clock::now();
  if (o.live) {
    run_live(o, pipeline, source, [&](const DepthFrame& f, const PipelineFrame& r) { handler(f, r); });
  } else {
    run_in_frame_order(pipeline, source, o.camera, {o.threads, 0, o.max_frames},
                       [&](const DepthFrame& f, PipelineFrame& r) { return handler(f, r); });
  }
  handler.finish();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Commits the CSV and prints what the run did.
void finish_run(const DetectOptions& o, const FrameSource& source, const PeoplePipeline& pipeline, DetectionCsv* csv,
                const FrameHandler& handler, double wall_s, bool with_models) {
  if (!source.summary().empty()) std::cerr << "rdsf-detect: " << source.summary() << "\n";
  if (csv) csv->commit();
  print_times(handler.total, handler.frames, handler.candidates, wall_s);
  if (with_models) std::cerr << "rdsf-detect: " << pipeline.tracker().people().size() << " people tracked\n";
  if (!o.out_csv.empty()) std::cerr << "rdsf-detect: wrote " << o.out_csv << "\n";
  if (!o.save_dir.empty()) std::cerr << "rdsf-detect: pictures in " << o.save_dir << "\n";
}

/// Sweeps every model's thresholds over the kept frames and writes the evaluation report.
void evaluate_models(const DetectOptions& o, const std::vector<BoostedModel>& models, const GroundTruth& truth,
                     const FrameHandler& handler, double wall_s) {
  std::vector<SweepResult> results;
  for (std::size_t m = 0; m < models.size(); ++m) {
    const BoostedModel& model = models[m];
    const double operating = o.pipeline.probability_threshold_for(model);
    results.push_back(sweep_thresholds(handler.evaluated[m], truth, o.thresholds, o.pipeline.tracking,
                                       model_label(model), model.calibration(), operating, o.clip_frames));
    results.back().fps = wall_s > 0 ? static_cast<double>(handler.frames) / wall_s : 0.0;
    // What the model file's validation predicted at (the kept level nearest) the operating probability.
    for (const ProbabilityPoint& p : model.training().validation.by_probability) {
      if (!results.back().validation ||
          std::abs(p.probability - operating) < std::abs(results.back().validation->probability - operating)) {
        results.back().validation = p;
      }
    }
  }
  std::cout << write_evaluation_report(results, o.report_dir);
  std::cerr << "rdsf-detect: report in " << o.report_dir << " (" << kEvaluationReportFiles << ")\n";
}

}  // namespace

void check_options(DetectOptions& o) {
  for (double p : o.thresholds) {
    if (!(p > 0.0 && p < 1.0)) throw cli::UsageError("--thresholds are probabilities inside (0, 1), got " + std::to_string(p));
  }
  if (o.candidates_only && !o.models.empty()) throw cli::UsageError("--candidates-only and --model exclude each other");
  // No model named: the default model, except for --truth without a model (candidate coverage only).
  if (o.models.empty() && !o.candidates_only && o.truth_csv.empty()) o.models.push_back(kDefaultModelName);
  if (o.max_frames < 0) throw cli::UsageError("--frames must be 0 (every frame) or more");
  if (o.live && (o.show || !o.truth_csv.empty())) throw cli::UsageError("--live works with --out and --save-dir, not with --show or --truth");
  if (!(o.fps > 0.0 && o.fps <= 1000.0)) throw cli::UsageError("--fps must be in (0, 1000], got " + std::to_string(o.fps));
  const bool evaluate = !o.truth_csv.empty();
  if (evaluate && !o.models.empty() && o.report_dir.empty()) {
    throw cli::UsageError("--truth with a --model needs --report-dir DIR for the evaluation report");
  }
  if (!o.report_dir.empty() && !evaluate) throw cli::UsageError("--report-dir needs --truth boxes.csv");
  if (!o.report_dir.empty() && o.models.empty()) throw cli::UsageError("--report-dir needs at least one --model to evaluate");
  if (o.out_csv.empty() && o.save_dir.empty() && !o.show && !evaluate && !o.live) {
    throw cli::UsageError("nothing to do: give --out FILE.csv, --save-dir DIR, --show or --truth with --report-dir");
  }
}

int run_detect(const DetectOptions& o) {
  check_outputs(o);
  const bool evaluate = !o.truth_csv.empty();
  std::vector<BoostedModel> models;
  for (const std::string& m : o.models) models.push_back(BoostedModel::load(m, o.models_dir));
  const GroundTruth truth = evaluate ? read_truth(o) : GroundTruth{};

  PeoplePipeline pipeline(pipeline_params_for(o, models), models.empty() ? nullptr : &models.front());
  auto source = open_frame_source(o.source, o.frames);
  if (evaluate) check_truth_frames(o, truth, *source);
  std::unique_ptr<DetectionCsv> csv;
  const BoxKind box = pipeline.params().analyser.reported_box;
  if (!o.out_csv.empty()) csv = std::make_unique<DetectionCsv>(o.out_csv, o.force, !models.empty(), box);
  if (!o.save_dir.empty()) create_save_dir(o.save_dir);
  announce(o, *source, models);

  FrameHandler handler(o, models, truth, pipeline, csv.get(), source->frame_count());
  const double wall_s = process_frames(o, pipeline, *source, handler);
  finish_run(o, *source, pipeline, csv.get(), handler, wall_s, !models.empty());

  if (evaluate) std::cerr << handler.coverage.summary(box);
  if (evaluate && !models.empty()) evaluate_models(o, models, truth, handler, wall_s);
  return 0;
}

}  // namespace rdsf
