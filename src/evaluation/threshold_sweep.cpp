#include "evaluation/threshold_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "candidates/candidate_finder.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "evaluation/curve_plot.hpp"
#include "frame/depth_png.hpp"

namespace rdsf {

const SweepRow& SweepResult::best_mota() const {
  if (rows.empty()) throw Error("evaluation of " + model + ": no thresholds");
  std::size_t best = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (rows[i].mot.mota() > rows[best].mot.mota()) best = i;
  }
  return rows[best];
}

double SweepResult::tar_at_fppf(double max_fppf) const {
  double tar = 0;
  for (const SweepRow& row : rows) {
    if (row.all.fppf <= max_fppf) tar = std::max(tar, row.all.tar);
  }
  return tar;
}

SweepResult sweep_thresholds(const std::vector<EvaluatedFrame>& frames, const GroundTruth& truth,
                             const std::vector<double>& thresholds, const TrackingParams& tracking,
                             const std::string& model_label) {
  SweepResult result;
  result.model = model_label;
  std::vector<FrameCandidates> scored;
  for (const EvaluatedFrame& f : frames) {
    FrameCandidates fc{f.frame, {}};
    for (const EvaluatedCandidate& c : f.candidates) fc.candidates.push_back({c.box, c.score});
    scored.push_back(std::move(fc));
  }
  result.segmentation_errors = segmentation_errors(scored, truth);
  for (double threshold : thresholds) {
    SweepRow row;
    row.all = detection_figures(scored, truth, threshold, false);
    row.clean = detection_figures(scored, truth, threshold, true);
    Tracker tracker(tracking);
    ClearMot mot;
    for (const EvaluatedFrame& f : frames) {
      std::vector<TrackInput> detections;
      for (const EvaluatedCandidate& c : f.candidates) {
        if (c.score >= threshold) detections.push_back({c.box, c.depth_mm, c.histogram});
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
    row.mot = mot.figures();
    result.rows.push_back(row);
  }
  return result;
}

namespace {

void write_table(std::ostream& out, const SweepResult& r, bool clean) {
  char line[256];
  std::snprintf(line, sizeof line, "  %9s %7s %7s %7s %7s %6s %7s %6s %7s %7s %7s %7s\n", "threshold", "TAR", "FAR",
                "TRR", "FRR", "n_fp", "n_det", "FPPF", "n_miss", "MPF", "MOTA", "MOTP");
  out << line;
  for (const SweepRow& row : r.rows) {
    const DetectionFigures& f = clean ? row.clean : row.all;
    std::snprintf(line, sizeof line, "  %9g %7.4f %7.4f %7.4f %7.4f %6ld %7ld %6.3f %7ld %7.3f %7.3f %7.1f\n",
                  f.threshold, f.tar, f.far, f.trr, f.frr, f.n_fp, f.n_det, f.fppf, f.n_miss, f.mpf, row.mot.mota(),
                  row.mot.motp());
    out << line;
  }
}

std::vector<cv::Point2d> sorted_points(std::vector<cv::Point2d> points) {
  std::sort(points.begin(), points.end(),
            [](const cv::Point2d& a, const cv::Point2d& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  return points;
}

}  // namespace

std::string write_evaluation_report(const std::vector<SweepResult>& results, const std::string& dir,
                                    double operating_threshold) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) fail(dir, "cannot create report folder: " + ec.message());
  const std::filesystem::path folder(dir);

  AtomicTextFile csv((folder / "metrics.csv").string(), true);
  csv.stream() << "model,table,threshold,n_frames,n_people,n_det,n_fp,n_miss,TAR,FAR,TRR,FRR,FPPF,MPF,"
                  "MOTA,MOTP,matches,misses,false_positives,mismatches\n";
  for (const SweepResult& r : results) {
    for (const SweepRow& row : r.rows) {
      for (int clean = 0; clean < 2; ++clean) {
        const DetectionFigures& f = clean ? row.clean : row.all;
        csv.stream() << r.model << ',' << (clean ? "without_segmentation_errors" : "all") << ',' << f.threshold
                     << ',' << f.n_frames << ',' << f.n_people << ',' << f.n_det << ',' << f.n_fp << ','
                     << f.n_miss << ',' << f.tar << ',' << f.far << ',' << f.trr << ',' << f.frr << ',' << f.fppf
                     << ',' << f.mpf << ',' << row.mot.mota() << ',' << row.mot.motp() << ',' << row.mot.matches
                     << ',' << row.mot.misses << ',' << row.mot.false_positives << ',' << row.mot.mismatches << '\n';
      }
    }
  }
  csv.commit();

  std::ostringstream summary;
  for (const SweepResult& r : results) {
    if (r.rows.empty()) continue;
    const SweepRow& best = r.best_mota();
    summary << "Model " << r.model << ": " << r.rows.front().all.n_frames << " frames, "
            << r.rows.front().all.n_people << " people, " << r.segmentation_errors
            << " segmentation errors (no candidate with IoU >= 0.5)";
    if (r.fps > 0) summary << ", " << std::lround(r.fps * 10) / 10.0 << " fps";
    summary << "\n";
    summary << " All people (FAR = n_fp / (n_fp + n_frames), as the thesis's tables):\n";
    write_table(summary, r, false);
    summary << " Without segmentation errors:\n";
    write_table(summary, r, true);
    char line[200];
    std::snprintf(line, sizeof line,
                  " Best MOTA %.3f at threshold %g (MOTP %.1f, %ld mismatches); TAR at FPPF <= 0.1: %.3f\n\n",
                  best.mot.mota(), best.all.threshold, best.mot.motp(), best.mot.mismatches, r.tar_at_fppf(0.1));
    summary << line;
  }
  AtomicTextFile text((folder / "summary.txt").string(), true);
  text.stream() << summary.str();
  text.commit();

  // The one-table view: models x TAR at FPPF 0.1, best MOTA, fps.
  AtomicTextFile table((folder / "summary.md").string(), true);
  table.stream() << "| model | TAR at FPPF <= 0.1 | best MOTA (threshold) | MOTP | segmentation errors | fps |\n"
                    "| --- | --- | --- | --- | --- | --- |\n";
  for (const SweepResult& r : results) {
    if (r.rows.empty()) continue;
    const SweepRow& best = r.best_mota();
    char row[256];
    std::snprintf(row, sizeof row, "| %s | %.3f | %.3f (%g) | %.1f | %ld of %ld | %.1f |\n", r.model.c_str(),
                  r.tar_at_fppf(0.1), best.mot.mota(), best.all.threshold, best.mot.motp(), r.segmentation_errors,
                  r.rows.front().all.n_people, r.fps);
    table.stream() << row;
  }
  table.commit();

  // Charts: every model on one ROC and one DET chart, the operating threshold marked.
  PlotAxes roc;
  roc.title = "ROC: true accept rate against false accept rate";
  roc.x_label = "FAR = n_fp / (n_fp + n_frames)";
  roc.y_label = "TAR (people detected)";
  PlotAxes det;
  det.title = "DET: miss rate against false positives per frame";
  det.x_label = "FPPF (false positives per frame, log)";
  det.y_label = "FRR (miss rate, log)";
  det.log_x = det.log_y = true;
  det.legend_bottom_left = true;  // DET curves fall from top left to bottom right
  roc.legend_bottom_left = false;
  det.x_min = 1e-3;
  det.x_max = 10;
  det.y_min = 1e-3;
  det.y_max = 1;
  std::vector<PlotCurve> roc_curves, det_curves;
  char label[64];
  std::snprintf(label, sizeof label, "T=%g", operating_threshold);
  for (const SweepResult& r : results) {
    PlotCurve rc{r.model, {}, std::nullopt, label}, dc{r.model, {}, std::nullopt, label};
    double closest = 1e300;
    for (const SweepRow& row : r.rows) {
      rc.points.emplace_back(row.all.far, row.all.tar);
      dc.points.emplace_back(std::max(row.all.fppf, det.x_min), std::max(row.all.frr, det.y_min));
      if (std::abs(row.all.threshold - operating_threshold) < closest) {
        closest = std::abs(row.all.threshold - operating_threshold);
        rc.operating_point = cv::Point2d(row.all.far, row.all.tar);
        dc.operating_point = cv::Point2d(std::max(row.all.fppf, det.x_min), std::max(row.all.frr, det.y_min));
        std::snprintf(label, sizeof label, "T=%g", row.all.threshold);
        rc.operating_label = dc.operating_label = label;
      }
    }
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
  return summary.str();
}

}  // namespace rdsf
