#include "rdsf/evaluation/threshold_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/core/atomic_file.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/classifier/roc_metrics.hpp"
#include "rdsf/evaluation/curve_plot.hpp"
#include "rdsf/evaluation/exact_curve.hpp"
#include "rdsf/frame/depth_png.hpp"

namespace rdsf {

const SweepRow& SweepResult::best_mota() const {
  if (rows.empty()) return operating;
  std::size_t best = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (rows[i].mot.mota() > rows[best].mot.mota()) best = i;
  }
  return operating.mot.mota() > rows[best].mot.mota() ? operating : rows[best];
}

namespace {

// The point of the exact curve with the highest TAR among those with FPPF <= max_fppf (the first of
// equals); nullptr when none qualifies.
const DetectionFigures* best_at_fppf(const std::vector<DetectionFigures>& curve, double max_fppf) {
  const DetectionFigures* best = nullptr;
  for (const DetectionFigures& f : curve) {
    if (f.fppf <= max_fppf && (best == nullptr || f.tar > best->tar)) best = &f;
  }
  return best;
}

}  // namespace

double SweepResult::tar_at_fppf(double max_fppf) const {
  const DetectionFigures* best = best_at_fppf(curve, max_fppf);
  return best != nullptr ? best->tar : 0.0;
}

RateInterval SweepResult::tar_interval_at_fppf(double max_fppf) const {
  const DetectionFigures* best = best_at_fppf(curve, max_fppf);
  return best != nullptr ? wilson_interval(best->n_det, best->n_people) : RateInterval{};
}

double SweepResult::candidate_recall() const {
  const long people = operating.all.n_people;
  return people > 0 ? static_cast<double>(people - segmentation_errors) / static_cast<double>(people) : 0.0;
}

std::vector<double> default_probability_thresholds() {
  std::vector<double> out = {0.01, 0.02};
  for (int k = 1; k <= 19; ++k) out.push_back(k * 0.05);
  out.push_back(0.98);
  out.push_back(0.99);
  return out;
}

namespace {

MotFigures tracking_figures(const std::vector<EvaluatedFrame>& frames, const GroundTruth& truth, double threshold,
                            const TrackingParams& tracking) {
  Tracker tracker(tracking);
  ClearMot mot;
  for (const EvaluatedFrame& f : frames) {
    std::vector<TrackInput> detections;
    std::vector<CandidateKin> kin;
    std::vector<double> scores;
    for (const EvaluatedCandidate& c : f.candidates) {
      kin.push_back(c.kin);
      scores.push_back(c.score);
    }
    const std::vector<char> duplicate = duplicate_candidates(kin, scores);
    for (std::size_t i = 0; i < f.candidates.size(); ++i) {
      const EvaluatedCandidate& c = f.candidates[i];
      if (c.score >= threshold && duplicate[i] == 0) detections.push_back({c.box, c.depth_mm, c.histogram});
    }
    const std::vector<int> ids = tracker.update(detections, f.camera, f.index);
    std::vector<TrackedBox> hypotheses, people;
    for (const TruthBox& t : truth.in(f.frame)) {
      if (!t.ignored) people.push_back({t.box, t.track});
    }
    for (std::size_t i = 0; i < detections.size(); ++i) {
      // A hypothesis on an ignored (hardly visible) person, and on no counted one, is left out.
      bool on_ignored = false, on_counted = false;
      for (const TruthBox& t : truth.in(f.frame)) {
        if (iou(detections[i].box, t.box) < 0.5) continue;
        (t.ignored ? on_ignored : on_counted) = true;
      }
      if (on_ignored && !on_counted) continue;
      hypotheses.push_back({detections[i].box, ids[i]});
    }
    mot.add_frame(people, hypotheses);
  }
  return mot.figures();
}

SweepRow row_at(const std::vector<EvaluatedFrame>& frames, const std::vector<FrameCandidates>& scored,
                const GroundTruth& truth, double probability, const ScoreCalibration& calibration,
                const TrackingParams& tracking) {
  const double threshold = calibration.score_at(probability);
  SweepRow row;
  row.probability = probability;
  row.all = detection_figures(scored, truth, threshold, false);
  row.clean = detection_figures(scored, truth, threshold, true);
  row.mot = tracking_figures(frames, truth, threshold, tracking);
  return row;
}

// Candidates covering a counted person are positives, those covering nobody (not even a don't-care
// person) negatives.
CandidateFigures classifier_figures(const std::vector<FrameCandidates>& scored, const GroundTruth& truth,
                                    double threshold) {
  std::vector<double> scores;
  std::vector<int> labels;
  for (const FrameCandidates& frame : scored) {
    for (const ScoredCandidate& c : frame.candidates) {
      bool counted = false, any = false;
      for (const TruthBox& t : truth.in(frame.frame)) {
        if (iou(c.box, t.box) < 0.5) continue;
        any = true;
        counted = counted || !t.ignored;
      }
      if (any && !counted) continue;
      scores.push_back(c.score);
      labels.push_back(counted ? 1 : 0);
    }
  }
  CandidateFigures f;
  f.positives = std::count(labels.begin(), labels.end(), 1);
  f.negatives = static_cast<long>(labels.size()) - f.positives;
  if (f.positives == 0 || f.negatives == 0) return f;
  f.auc = roc_auc(scores, labels);
  long tp = 0, fp = 0;
  for (std::size_t i = 0; i < scores.size(); ++i) {
    if (scores[i] >= threshold) (labels[i] == 1 ? tp : fp) += 1;
  }
  f.tar = static_cast<double>(tp) / static_cast<double>(f.positives);
  f.tar_interval = wilson_interval(tp, f.positives);
  f.far = static_cast<double>(fp) / static_cast<double>(f.negatives);
  return f;
}

}  // namespace

SweepResult sweep_thresholds(const std::vector<EvaluatedFrame>& frames, const GroundTruth& truth,
                             const std::vector<double>& probabilities, const TrackingParams& tracking,
                             const std::string& model_label, const ScoreCalibration& calibration,
                             double operating_probability, int clip_frames) {
  SweepResult result;
  result.model = model_label;
  result.operating_probability = operating_probability;
  std::vector<FrameCandidates> scored;
  for (const EvaluatedFrame& f : frames) {
    FrameCandidates fc{f.frame, {}};
    for (const EvaluatedCandidate& c : f.candidates) fc.candidates.push_back({c.box, c.score, c.kin});
    scored.push_back(std::move(fc));
  }
  result.segmentation_errors = segmentation_errors(scored, truth);
  for (double p : probabilities) result.rows.push_back(row_at(frames, scored, truth, p, calibration, tracking));
  result.operating = row_at(frames, scored, truth, operating_probability, calibration, tracking);
  result.curve = exact_detection_curve(scored, truth, false);
  for (const DetectionFigures& f : result.curve) result.curve_probability.push_back(calibration.probability(f.threshold));
  result.candidates = classifier_figures(scored, truth, calibration.score_at(operating_probability));
  result.by_clip = std::make_shared<const ClipResampler>(scored, truth, clip_frames);
  result.clip_frames = clip_frames;
  result.clips = result.by_clip->figures(calibration.score_at(operating_probability));
  result.clip_interval_01 = result.by_clip->interval(0.1);
  result.clip_interval_05 = result.by_clip->interval(0.5);
  return result;
}

namespace {

void write_table(std::ostream& out, const SweepResult& r, bool clean) {
  char line[256];
  std::snprintf(line, sizeof line, "  %6s %9s %7s %7s %7s %7s %6s %7s %6s %7s %7s %7s %7s\n", "P >=", "H(x) >=",
                "TAR", "FAR", "TRR", "FRR", "n_fp", "n_det", "FPPF", "n_miss", "MPF", "MOTA", "MOTP");
  out << line;
  for (const SweepRow& row : r.rows) {
    const DetectionFigures& f = clean ? row.clean : row.all;
    std::snprintf(line, sizeof line, "  %6.2f %9.3f %7.4f %7.4f %7.4f %7.4f %6ld %7ld %6.3f %7ld %7.3f %7.3f %7.1f\n",
                  row.probability, f.threshold, f.tar, f.far, f.trr, f.frr, f.n_fp, f.n_det, f.fppf, f.n_miss, f.mpf,
                  row.mot.mota(), row.mot.motp());
    out << line;
  }
}

std::vector<cv::Point2d> sorted_points(std::vector<cv::Point2d> points) {
  std::sort(points.begin(), points.end(),
            [](const cv::Point2d& a, const cv::Point2d& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  return points;
}

// metrics.csv: per model, table row and figure set (all people, without segmentation errors) a line.
void write_metrics_csv(const std::vector<SweepResult>& results, const std::filesystem::path& folder) {
  AtomicTextFile csv((folder / "metrics.csv").string(), true);
  csv.stream() << "model,table,probability,threshold,n_frames,n_people,n_det,n_fp,n_miss,TAR,FAR,TRR,FRR,FPPF,MPF,"
                  "MOTA,MOTP,matches,misses,false_positives,mismatches\n";
  for (const SweepResult& r : results) {
    for (const SweepRow& row : r.rows) {
      for (int clean = 0; clean < 2; ++clean) {
        const DetectionFigures& f = clean ? row.clean : row.all;
        csv.stream() << r.model << ',' << (clean ? "without_segmentation_errors" : "all") << ',' << row.probability
                     << ',' << f.threshold
                     << ',' << f.n_frames << ',' << f.n_people << ',' << f.n_det << ',' << f.n_fp << ','
                     << f.n_miss << ',' << f.tar << ',' << f.far << ',' << f.trr << ',' << f.frr << ',' << f.fppf
                     << ',' << f.mpf << ',' << row.mot.mota() << ',' << row.mot.motp() << ',' << row.mot.matches
                     << ',' << row.mot.misses << ',' << row.mot.false_positives << ',' << row.mot.mismatches << '\n';
      }
    }
  }
  csv.commit();
}

// curve.csv: every point of every model's exact curve.
void write_curve_csv(const std::vector<SweepResult>& results, const std::filesystem::path& folder) {
  AtomicTextFile curve_csv((folder / "curve.csv").string(), true);
  curve_csv.stream() << "model,probability,threshold,n_frames,n_people,n_det,n_fp,TAR,FAR,FPPF,FRR\n";
  for (const SweepResult& r : results) {
    for (std::size_t k = 0; k < r.curve.size(); ++k) {
      const DetectionFigures& f = r.curve[k];
      curve_csv.stream() << r.model << ',' << r.curve_probability[k] << ',' << f.threshold << ',' << f.n_frames << ','
                         << f.n_people << ',' << f.n_det << ',' << f.n_fp << ',' << f.tar << ',' << f.far << ','
                         << f.fppf << ',' << f.frr << '\n';
    }
  }
  curve_csv.commit();
}

// "95 % intervals of TAR at FPPF <= 0.1 / 0.5 over the 16 clips: 0.55-0.86, 0.60-0.90", or why there are none.
std::string clip_interval_text(const ClipInterval& at01, const ClipInterval& at05) {
  if (!at01.known()) {
    return at01.clips == 1 ? "one clip: no interval over clips (one scene says nothing of other rooms)"
                           : "no interval over clips (nobody counted in them)";
  }
  char text[240];
  std::snprintf(text, sizeof text, "95 %% intervals of TAR at FPPF <= 0.1 / 0.5 over the %d clips: %.2f-%.2f, %.2f-%.2f%s",
                at01.clips, at01.interval.low, at01.interval.high, at05.interval.low, at05.interval.high,
                at01.few() ? " (few clips: a bootstrap over so few understates the spread; read the wider interval)" : "");
  return text;
}

// "Clips with the fewest people found at the operating point (...): #4 14 of 85 (14 with a candidate, 2 false
// positives), ..."
std::string weakest_clips_text(std::vector<ClipFigures> clips, std::size_t most) {
  clips.erase(std::remove_if(clips.begin(), clips.end(), [](const ClipFigures& c) { return c.people == 0; }), clips.end());
  const auto found = [](const ClipFigures& c) { return static_cast<double>(c.detected) / static_cast<double>(c.people); };
  std::stable_sort(clips.begin(), clips.end(), [&](const ClipFigures& a, const ClipFigures& b) { return found(a) < found(b); });
  std::string text = "Clips with the fewest people found at the operating point (clips.csv has each):";
  for (std::size_t i = 0; i < clips.size() && i < most; ++i) {
    text += (i ? ", " : " ") + clips[i].clip + " " + std::to_string(clips[i].detected) + " of " +
            std::to_string(clips[i].people) + " (" + std::to_string(clips[i].with_candidate) + " with a candidate, " +
            std::to_string(clips[i].false_positives) + (clips[i].false_positives == 1 ? " false positive)" : " false positives)");
  }
  return text;
}

// The end of summary.txt with two or more models: each later one against the first, paired over clips.
std::string paired_differences_text(const std::vector<SweepResult>& results) {
  if (results.size() < 2 || !results[0].by_clip) return "";
  std::string text = "Against " + results[0].model + ", paired over the same clips (95 % intervals; a difference "
                     "whose interval holds 0 is not shown by these frames):\n";
  for (std::size_t m = 1; m < results.size(); ++m) {
    if (!results[m].by_clip) continue;
    text += " " + results[m].model + ":";
    for (double max_fppf : {0.1, 0.5}) {
      const ClipDifference d = paired_difference(*results[0].by_clip, *results[m].by_clip, max_fppf);
      char part[160];
      if (d.interval.known()) {
        std::snprintf(part, sizeof part, " TAR at FPPF <= %.1f %+.3f (%+.3f to %+.3f over %d clips)%s", max_fppf,
                      d.difference, d.interval.interval.low, d.interval.interval.high, d.interval.clips,
                      d.interval.few() ? " few" : "");
      } else {
        std::snprintf(part, sizeof part, " TAR at FPPF <= %.1f %+.3f (one clip: no interval)", max_fppf, d.difference);
      }
      text += part;
      if (max_fppf == 0.1) text += ";";
    }
    text += "\n";
  }
  return text;
}

// One model's part of summary.txt: its tables, best MOTA, the exact curve and the operating point.
void write_model_summary(std::ostream& out, const SweepResult& r) {
  const SweepRow& best = r.best_mota();
  out << "Model " << r.model << ": " << r.operating.all.n_frames << " frames, " << r.operating.all.n_people
      << " people, " << r.segmentation_errors << " segmentation errors (no candidate with IoU >= 0.5)";
  if (r.fps > 0) out << ", " << std::lround(r.fps * 10) / 10.0 << " fps";
  out << "\n";
  out << " All people (FAR = n_fp / (n_fp + n_frames), as the thesis's tables):\n";
  write_table(out, r, false);
  out << " Without segmentation errors:\n";
  write_table(out, r, true);
  char line[400];
  const RateInterval tar01 = r.tar_interval_at_fppf(0.1), tar05 = r.tar_interval_at_fppf(0.5);
  std::snprintf(line, sizeof line,
                " Best MOTA %.3f at P >= %.2f (MOTP %.1f, %ld mismatches); exact curve: TAR %.3f at FPPF <= 0.1, "
                "%.3f at FPPF <= 0.5 (95 %% intervals over the %ld people: %.2f-%.2f, %.2f-%.2f)\n",
                best.mot.mota(), best.probability, best.mot.motp(), best.mot.mismatches, r.tar_at_fppf(0.1),
                r.tar_at_fppf(0.5), r.operating.all.n_people, tar01.low, tar01.high, tar05.low, tar05.high);
  out << line << " By clip: " << clip_interval_text(r.clip_interval_01, r.clip_interval_05) << "\n";
  out << " " << weakest_clips_text(r.clips, 3) << "\n";
  std::snprintf(line, sizeof line,
                " At the operating point P >= %.2f: TAR %.3f, FPPF %.3f, MOTA %.3f. Classifier on the %ld + %ld "
                "candidates: AUC %.4f, TAR %.3f, FAR %.3f",
                r.operating_probability, r.operating.all.tar, r.operating.all.fppf, r.operating.mot.mota(),
                r.candidates.positives, r.candidates.negatives, r.candidates.auc, r.candidates.tar, r.candidates.far);
  out << line;
  if (r.validation) {
    std::snprintf(line, sizeof line,
                  "; the model file's validation said TAR %.3f, FAR %.3f (gap %+.3f; the held-out TAR's 95 %% "
                  "interval over %ld positives is %.3f-%.3f)",
                  r.validation->tar, r.validation->far, r.candidates.tar - r.validation->tar, r.candidates.positives,
                  r.candidates.tar_interval.low, r.candidates.tar_interval.high);
    out << line;
  }
  out << "\n\n";
}

// summary.md, the one-table view: models x TAR at FPPF 0.1, best MOTA, fps.
void write_summary_md(const std::vector<SweepResult>& results, const std::filesystem::path& folder) {
  AtomicTextFile table((folder / "summary.md").string(), true);
  table.stream() << "| model | TAR at FPPF <= 0.1 | TAR at FPPF <= 0.5 | best MOTA (P >=) | MOTP | candidate recall | "
                    "candidate AUC | TAR at P >= op: validation / held-out (gap; held-out 95 % interval) | fps | "
                    "TAR at FPPF <= 0.1 / 0.5: 95 % interval over the people | ... over clips (clips) |\n"
                    "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const SweepResult& r : results) {
    const SweepRow& best = r.best_mota();
    char validation[128] = "no validation";
    if (r.validation) {
      std::snprintf(validation, sizeof validation, "%.3f / %.3f (%+.3f; 95 %% %.2f-%.2f)", r.validation->tar,
                    r.candidates.tar, r.candidates.tar - r.validation->tar, r.candidates.tar_interval.low,
                    r.candidates.tar_interval.high);
    }
    const RateInterval tar01 = r.tar_interval_at_fppf(0.1), tar05 = r.tar_interval_at_fppf(0.5);
    char by_clip[96];
    std::snprintf(by_clip, sizeof by_clip, "%s", r.clip_interval_01.clips == 1 ? "one clip" : "none");
    if (r.clip_interval_01.known()) {
      std::snprintf(by_clip, sizeof by_clip, "%.2f-%.2f / %.2f-%.2f (%d%s)", r.clip_interval_01.interval.low,
                    r.clip_interval_01.interval.high, r.clip_interval_05.interval.low, r.clip_interval_05.interval.high,
                    r.clip_interval_01.clips, r.clip_interval_01.few() ? ", few" : "");
    }
    char row[720];
    std::snprintf(row, sizeof row,
                  "| %s | %.3f | %.3f | %.3f (%.2f) | %.1f | %.3f (%ld of %ld) | %.4f | %s at %.2f | %.1f | %.2f-%.2f / "
                  "%.2f-%.2f | %s |\n",
                  r.model.c_str(), r.tar_at_fppf(0.1), r.tar_at_fppf(0.5), best.mot.mota(), best.probability,
                  best.mot.motp(), r.candidate_recall(), r.operating.all.n_people - r.segmentation_errors,
                  r.operating.all.n_people, r.candidates.auc, validation, r.operating_probability, r.fps, tar01.low,
                  tar01.high, tar05.low, tar05.high, by_clip);
    table.stream() << row;
  }
  table.commit();
}

// clips.csv: every model's clips at its operating probability.
void write_clips_csv(const std::vector<SweepResult>& results, const std::filesystem::path& folder) {
  AtomicTextFile csv((folder / "clips.csv").string(), true);
  csv.stream() << "model,clip_frames,probability,clip,frames,people,with_candidate,detected,false_positives\n";
  for (const SweepResult& r : results) {
    for (const ClipFigures& c : r.clips) {
      csv.stream() << r.model << ',' << r.clip_frames << ',' << r.operating_probability << ',' << c.clip << ','
                   << c.frames << ',' << c.people << ',' << c.with_candidate << ',' << c.detected << ','
                   << c.false_positives << '\n';
    }
  }
  csv.commit();
}

// outcomes.csv: every model's candidates with their clip, H(x) (17 digits: equal scores stay equal, they are
// one point of the exact curve) and outcome, score descending: enough to redo the exact curve of any set of
// clips, weighted (scripts/paired-clips.py pairs two runs' curves over their clips this way).
void write_outcomes_csv(const std::vector<SweepResult>& results, const std::filesystem::path& folder) {
  AtomicTextFile csv((folder / "outcomes.csv").string(), true);
  csv.stream() << "model,clip,score,outcome\n" << std::setprecision(17);
  for (const SweepResult& r : results) {
    if (!r.by_clip) continue;
    const std::vector<std::string>& names = r.by_clip->names();
    for (const ClipResampler::Outcome& o : r.by_clip->outcomes()) {
      csv.stream() << r.model << ',' << names[static_cast<std::size_t>(o.clip)] << ',' << o.score << ','
                   << (o.kind > 0 ? "detection" : (o.kind < 0 ? "false_positive" : "neutral")) << '\n';
    }
  }
  csv.commit();
}

// roc.png and det.png: every model on one ROC and one DET chart, the operating threshold marked.
void write_charts(const std::vector<SweepResult>& results, const std::filesystem::path& folder) {
  PlotAxes roc;
  roc.title = "ROC: true accept rate against false accept rate";
  roc.x_label = "FAR = n_fp / (n_fp + n_frames)";
  roc.y_label = "TAR (people detected)";
  PlotAxes det;
  det.title = "DET: miss rate against false positives per frame";
  det.x_label = "FPPF (false positives per frame, log)";
  det.y_label = "FRR (miss rate, log)";
  det.log_x = det.log_y = true;
  det.legend = PlotAxes::Corner::bottom_left;  // DET curves fall from top left to bottom right
  roc.legend = PlotAxes::Corner::bottom_right;  // ROC curves rise to the top left and run along the top
  det.x_min = 1e-3;
  det.x_max = 10;
  det.y_min = 1e-3;
  det.y_max = 1;
  std::vector<PlotCurve> roc_curves, det_curves;
  for (const SweepResult& r : results) {
    char label[64];
    std::snprintf(label, sizeof label, "P>=%.2f", r.operating_probability);
    PlotCurve rc{r.model, {}, std::nullopt, label}, dc{r.model, {}, std::nullopt, label};
    rc.points.emplace_back(0.0, 0.0);
    for (const DetectionFigures& f : r.curve) {
      rc.points.emplace_back(f.far, f.tar);
      dc.points.emplace_back(std::max(f.fppf, det.x_min), std::max(f.frr, det.y_min));
    }
    const DetectionFigures& op = r.operating.all;
    rc.operating_point = cv::Point2d(op.far, op.tar);
    dc.operating_point = cv::Point2d(std::max(op.fppf, det.x_min), std::max(op.frr, det.y_min));
    rc.points = sorted_points(rc.points);
    dc.points = sorted_points(dc.points);
    roc_curves.push_back(rc);
    det_curves.push_back(dc);
  }
  double max_far = 0.05;
  for (const PlotCurve& c : roc_curves) {
    for (const cv::Point2d& p : c.points) max_far = std::max(max_far, p.x);
  }
  roc.x_max = std::min(1.0, max_far * 1.1);
  write_png_atomically((folder / "roc.png").string(), draw_plot(roc, roc_curves));
  write_png_atomically((folder / "det.png").string(), draw_plot(det, det_curves));
}

}  // namespace

std::string write_evaluation_report(const std::vector<SweepResult>& results, const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) fail(dir, "cannot create report folder: " + ec.message());
  const std::filesystem::path folder(dir);
  write_metrics_csv(results, folder);
  write_curve_csv(results, folder);
  write_clips_csv(results, folder);
  write_outcomes_csv(results, folder);
  std::ostringstream summary;
  for (const SweepResult& r : results) write_model_summary(summary, r);
  summary << paired_differences_text(results);
  AtomicTextFile text((folder / "summary.txt").string(), true);
  text.stream() << summary.str();
  text.commit();
  write_summary_md(results, folder);
  write_charts(results, folder);
  return summary.str();
}

}  // namespace rdsf
