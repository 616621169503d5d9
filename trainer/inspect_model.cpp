// rdsf-train --inspect: what a model file says about itself, and which features it uses most.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/classifier/model_file.hpp"
#include "rdsf/pipeline/stated_options.hpp"
#include "trainer/train_run.hpp"

namespace rdsf {
namespace {

struct FeatureUse {
  int feature = 0;
  int uses = 0;
  double spread = 0.0;  // sum over its weak classifiers of (highest - lowest response) / 2
};

// "  3 (row  0, col 3)" for a cell, "16x16 at (8, 24)" for a square.
std::string region_text(const FeatureSpec& spec, int region) {
  char text[48];
  if (spec.layout == FeatureSpec::Layout::Cells) {
    std::snprintf(text, sizeof text, "%3d (row %2d, col %d)", region, region / spec.cells_x(), region % spec.cells_x());
  } else {
    const FeatureRegion r = spec.region(region);
    std::snprintf(text, sizeof text, "%dx%d at (%d, %d)", r.width, r.height, r.x, r.y);
  }
  return text;
}

// The model's identity: name, format, features, crops, classifier, calibration, backend, recipe, parameters.
void print_identity(const BoostedModel& model, std::ostream& out) {
  const TrainingRecord& t = model.training();
  const FeatureSpec& spec = model.feature_spec();
  char line[512];
  out << "model        " << model_label(model) << "  (" << model.path() << ")\n";
  out << "format       " << kModelFormat << " version " << model.format_version() << ", created " << model.created()
      << "\n";
  out << "features     " << spec.canonical() << "  (hash " << spec.hash() << ")\n";
  if (t.crops.known()) {
    std::snprintf(line, sizeof line, "crops        window = %s box x %g\n", t.crops.window_box.c_str(),
                  t.crops.window_scale);
    out << line;
  } else {
    out << "crops        not recorded (" << (model.format_version() < 3 ? "format " + std::to_string(model.format_version())
                                                                     : std::string("by the training sets"))
        << "): not checked\n";
  }
  const WeakClassifier::Kind kind =
      model.weak_classifiers().empty() ? WeakClassifier::Kind::Lut : model.weak_classifiers().front().kind;
  const std::string tables = "look-up tables of " + std::to_string(model.bins().count) + " bins";
  out << "classifier   " << model.weak_classifiers().size() << " weak classifiers, "
      << (kind == WeakClassifier::Kind::Lut    ? tables
          : kind == WeakClassifier::Kind::Tree ? "trees of depth " + std::to_string(model.weak_classifiers().front().depth()) +
                                                     " (" + tables + ", " +
                                                     std::to_string(model.used_features().size()) + " features read)"
                                               : std::string("stumps"))
      << (model.opencv_model_yaml().empty() ? "" : ", embedded OpenCV model") << "\n";
  const ScoreCalibration& c = model.calibration();
  std::snprintf(line, sizeof line, "calibration  %s: P(person) = 1 / (1 + exp(-(%.4f H %+.4f)))%s%s\n", c.method.c_str(),
                c.a, c.b, c.source.empty() ? "" : ", fitted on ", c.source.c_str());
  out << line;
  std::snprintf(line, sizeof line, "operating    P(person) >= %.2f: ", model.operating_probability());
  out << line << (model.operating_point() ? model.operating_point()->rule : std::string("none stated (the default 0.5)"))
      << "\n";
  const std::string departures = option_words(departures_from_defaults(model.detection_options()));
  out << "detection    "
      << (model.detection_options().empty() ? std::string("no options stated (the detector's own)")
          : departures.empty()              ? std::string("states this build's default options")
                                            : "states " + departures + " (the rest at this build's defaults)")
      << "\n";
  out << "backend      " << t.backend << "\n";
  out << "recipe       " << t.recipe << "\n";
  out << "parameters  ";
  for (const auto& [key, value] : t.parameters) out << " " << key << "=" << value;
  out << "\n";
}

// What it was trained on and how it validated: sample sets, counts, validation figures, ROC, rounds.
void print_training(const TrainingRecord& t, std::ostream& out) {
  char line[512];
  out << "sample sets\n";
  for (const SampleSetUse& s : t.sample_sets) {
    std::snprintf(line, sizeof line, "  %-15s %-40s manifest %-16s used %zu of %zu\n", s.role.c_str(), s.path.c_str(),
                  s.manifest_hash.empty() ? "-" : s.manifest_hash.c_str(), s.used, s.available);
    out << line;
  }
  out << "training     " << t.train_positives << " positives, " << t.train_negatives << " negatives; " << t.stopped
      << "\n";
  const ValidationFigures& v = t.validation;
  out << "validation   " << v.source << ": " << v.positives << " positives, " << v.negatives << " negatives\n";
  if (v.positives > 0 && v.negatives > 0) {
    std::snprintf(line, sizeof line, "             AUC %.4f   TAR %.4f at FAR 1%%   TAR %.4f at FAR 5%%   error %.4f\n",
                  v.summary.auc, v.summary.tar_at_far_1, v.summary.tar_at_far_5, v.summary.error_rate);
    out << line;
    out << "ROC          ";
    for (const RocPoint& p : v.roc) {
      std::snprintf(line, sizeof line, " FAR %.4f->TAR %.4f", p.far, p.tar);
      out << line;
    }
    out << "\n";
    if (!v.by_probability.empty()) {
      out << "by P(person) ";
      for (const ProbabilityPoint& p : v.by_probability) {
        if (std::lround(p.probability * 100) % 10 != 0) continue;  // 0.1, 0.2, ..., 0.9
        std::snprintf(line, sizeof line, " P>=%.1f: TAR %.3f FAR %.3f", p.probability, p.tar, p.far);
        out << line;
      }
      out << "\n";
    }
  }
  if (!v.rounds.empty()) {
    out << "rounds        round  feature  train err  val err     AUC   TAR@1%  TAR@5%\n";
    for (const RoundFigures& r : v.rounds) {
      std::snprintf(line, sizeof line, "             %6d  %7d   %.4f    %.4f   %.4f  %.4f  %.4f\n", r.round, r.feature,
                    r.train_error, r.validation.error_rate, r.validation.auc, r.validation.tar_at_far_1,
                    r.validation.tar_at_far_5);
      out << line;
    }
  }
}

// The features of the weak classifiers, most used first (ties: the larger spread first).
std::vector<FeatureUse> ranked_feature_uses(const BoostedModel& model) {
  std::map<int, FeatureUse> uses;
  for (const WeakClassifier& w : model.weak_classifiers()) {
    FeatureUse& u = uses[w.feature];
    u.feature = w.feature;
    ++u.uses;
    if (w.kind == WeakClassifier::Kind::Lut) {
      const auto [lo, hi] = std::minmax_element(w.responses.begin(), w.responses.end());
      u.spread += (*hi - *lo) / 2.0;
    } else {
      u.spread += std::abs(w.right - w.left) / 2.0;
    }
  }
  std::vector<FeatureUse> ranked;
  for (const auto& [feature, use] : uses) ranked.push_back(use);
  std::stable_sort(ranked.begin(), ranked.end(), [](const FeatureUse& a, const FeatureUse& b) {
    return a.uses != b.uses ? a.uses > b.uses : a.spread > b.spread;
  });
  return ranked;
}

// The first `top` of `ranked` with the pair of regions each feature compares.
void print_feature_uses(const std::vector<FeatureUse>& ranked, const FeatureSpec& spec, int top, std::ostream& out) {
  char line[512];
  out << "most used features (" << ranked.size() << " distinct; spread = sum of (max - min response) / 2)\n";
  out << "  rank  feature  uses  spread   " << (spec.layout == FeatureSpec::Layout::Cells ? "cell" : "square")
      << " pair\n";
  for (std::size_t k = 0; k < ranked.size() && k < static_cast<std::size_t>(std::max(0, top)); ++k) {
    int i = 0, j = 0;
    spec.pair_at(ranked[k].feature, i, j);
    std::snprintf(line, sizeof line, "  %4zu  %7d  %4d  %6.3f   %s - %s\n", k + 1, ranked[k].feature, ranked[k].uses,
                  ranked[k].spread, region_text(spec, i).c_str(), region_text(spec, j).c_str());
    out << line;
  }
}

}  // namespace

int run_inspect(const TrainOptions& o, std::ostream& out) {
  const BoostedModel model = BoostedModel::load(o.inspect, o.models_dir);
  print_identity(model, out);
  print_training(model.training(), out);
  print_feature_uses(ranked_feature_uses(model), model.feature_spec(), o.top, out);
  return 0;
}

}  // namespace rdsf
