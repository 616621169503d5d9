#include "labeler_bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>

#include "rdsf/candidates/candidate_finder.hpp"
#include "rdsf/classifier/seeded_sampling.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/evaluation/ground_truth.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/labeling/active_learning.hpp"

namespace rdsf::bench {
namespace {

struct Pool {
  cv::Mat1f rows;
  std::vector<int> labels;
  std::vector<SampleOrigin> origins;
  std::int64_t frames = 0;
};

// Every candidate the truth is sure of, with its features (see the header for the rule).
void add_recording(const std::string& dir, const FrameAnalyser& analyser, Pool& pool) {
  GroundTruth truth = read_ground_truth((std::filesystem::path(dir) / "boxes.csv").string());
  ignore_hardly_visible(truth, 0.5);
  auto source = open_frame_source(dir, CameraModel{});
  DepthFrame frame;
  while (source->next(frame)) {
    ++pool.frames;
    const FrameAnalysis a = analyser.analyse(frame, /*with_features=*/true);
    for (std::size_t i = 0; i < a.candidates.size(); ++i) {
      const TruthOverlap overlap =
          truth_overlap(labelling_box(a.candidates[i], analyser.params().reported_box), truth.in(frame.name));
      int label = -1;
      if (overlap.counted >= 0.5) label = 1;
      if (overlap.counted < 0.3 && overlap.ignored < 0.3) label = 0;
      if (label < 0) continue;
      pool.rows.push_back(a.features.row(static_cast<int>(i)));
      pool.labels.push_back(label);
      pool.origins.push_back({dir, frame.name});
    }
  }
  std::fprintf(stderr, "rdsf-labeler-bench: %s: %lld frames so far, %zu candidates\n", dir.c_str(),
               static_cast<long long>(pool.frames), pool.labels.size());
}

Pool load(const std::vector<std::string>& dirs, const FrameAnalyser& analyser) {
  Pool pool;
  for (const std::string& d : dirs) add_recording(d, analyser, pool);
  return pool;
}

Pool subset(const Pool& pool, const std::vector<std::size_t>& rows, const std::vector<int>* labels = nullptr) {
  Pool out;
  out.rows.create(static_cast<int>(rows.size()), pool.rows.cols);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    pool.rows.row(static_cast<int>(rows[k])).copyTo(out.rows.row(static_cast<int>(k)));
    out.labels.push_back(labels ? (*labels)[rows[k]] : pool.labels[rows[k]]);
    out.origins.push_back(pool.origins[rows[k]]);
  }
  return out;
}

std::vector<double> probabilities(const BoostedModel& model, const cv::Mat1f& rows) {
  std::vector<double> p = model.score(rows);
  for (double& v : p) v = model.probability(v);
  return p;
}

// TAR at FPPF <= max_fppf over held-out candidates (header).
double tar_at_fppf(const BoostedModel& model, const Pool& test, double max_fppf) {
  const std::vector<double> s = model.score(test.rows);
  std::vector<double> neg, pos;
  for (std::size_t i = 0; i < s.size(); ++i) (test.labels[i] == 1 ? pos : neg).push_back(s[i]);
  std::sort(neg.begin(), neg.end(), std::greater<>());
  const auto allowed = static_cast<std::size_t>(std::floor(max_fppf * static_cast<double>(test.frames)));
  // Persons must score above the (allowed+1)-th highest not-person score.
  const double threshold = allowed < neg.size() ? neg[allowed] : -1e300;
  const auto above = std::count_if(pos.begin(), pos.end(), [&](double v) { return v > threshold; });
  return pos.empty() ? 0.0 : static_cast<double>(above) / static_cast<double>(pos.size());
}

struct LoopResult {
  std::size_t answers = 0;  ///< answers when the target was first reached (pool size when never)
  bool reached = false;
  double tar = 0;
  std::optional<BoostedModel> model;
  std::vector<std::size_t> asked;
  std::vector<std::pair<std::size_t, double>> curve;  ///< answers, held-out TAR
};

LoopResult run_loop(const Pool& pool, const Pool& test, double target, const LabelerBenchOptions& o, bool active,
                    const LoopTrainingParams& params) {
  LoopResult r;
  const std::size_t n = pool.labels.size();
  const std::vector<std::size_t> random_order = seeded_permutation(n, o.seed);
  std::vector<bool> asked(n, false);
  std::size_t next_random = 0;
  auto take = [&](std::size_t i) {
    asked[i] = true;
    r.asked.push_back(i);
  };
  while (r.asked.size() < n) {
    const std::size_t want = std::min(n, r.asked.size() + static_cast<std::size_t>(o.batch));
    if (active && r.model) {
      // As rdsf-label --loop: most uncertain first, every explore-th a random one.
      const std::vector<double> p = probabilities(*r.model, pool.rows);
      const std::vector<std::size_t> order = most_uncertain_first(p);
      std::size_t next = 0, k = 0;
      while (r.asked.size() < want) {
        if (o.explore > 0 && ++k % static_cast<std::size_t>(o.explore) == 0) {
          while (asked[random_order[next_random]]) ++next_random;
          take(random_order[next_random]);
        } else {
          while (asked[order[next]]) ++next;
          take(order[next]);
        }
      }
    } else {
      while (r.asked.size() < want) {
        const std::size_t i = random_order[next_random++];
        if (!asked[i]) take(i);
      }
    }
    const Pool labelled = subset(pool, r.asked);
    r.model = train_loop_model(labelled.rows, labelled.labels, labelled.origins, FeatureSpec{}, params);
    if (!r.model) continue;
    r.tar = tar_at_fppf(*r.model, test, 0.1);
    r.curve.emplace_back(r.asked.size(), r.tar);
    if (r.tar >= target) {
      r.reached = true;
      break;
    }
  }
  r.answers = r.asked.size();
  return r;
}

struct AnswerQuality {
  std::size_t answered = 0, wrong = 0, total = 0;
};

AnswerQuality model_answers(const std::vector<double>& p, const std::vector<int>& labels,
                            const std::vector<bool>* skip, double accept, double reject) {
  AnswerQuality q;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (skip && (*skip)[i]) continue;
    ++q.total;
    if (p[i] >= accept || p[i] <= reject) {
      ++q.answered;
      if ((p[i] >= accept) != (labels[i] == 1)) ++q.wrong;
    }
  }
  return q;
}

std::string percent(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f%%", v * 100.0);
  return text;
}

// The pool, the held-out set, the all-labelled model's TAR and how many answers each loop needed.
void print_loops(const Pool& pool, const Pool& test, double target, const LoopResult& active, const LoopResult& passive) {
  const auto positives = std::count(pool.labels.begin(), pool.labels.end(), 1);
  std::printf("| pool (training recordings) | %zu candidates (%ld persons) in %lld frames |\n", pool.labels.size(),
              static_cast<long>(positives), static_cast<long long>(pool.frames));
  std::printf("| --- | --- |\n");
  std::printf("| held-out | %zu candidates in %lld frames |\n", test.labels.size(), static_cast<long long>(test.frames));
  std::printf("| all-labelled model: held-out TAR at FPPF <= 0.1 | %.3f |\n", target);
  auto loop_row = [&](const char* what, const LoopResult& r) {
    std::printf("| %s: human answers to reach it | %zu of %zu (%s)%s, TAR %.3f |\n", what, r.answers,
                pool.labels.size(), percent(static_cast<double>(r.answers) / static_cast<double>(pool.labels.size())).c_str(),
                r.reached ? "" : " (not reached)", r.tar);
  };
  loop_row("active learning (most uncertain first)", active);
  loop_row("passive (random order)", passive);
}

// Model answers at the given thresholds and a sweep: wrong answers of the all-labelled model on the held-out
// set, and of the active loop's model on the pool it did not ask.
void print_model_answers(const LabelerBenchOptions& o, const BoostedModel& all, const Pool& pool, const Pool& test,
                         const LoopResult& active) {
  const std::vector<double> held_out_p = probabilities(all, test.rows);
  std::vector<bool> trained_on(pool.labels.size(), false);
  for (std::size_t i : active.asked) trained_on[i] = true;
  const std::vector<double> rest_p = active.model ? probabilities(*active.model, pool.rows) : std::vector<double>{};
  std::vector<std::pair<double, double>> sweep{{o.accept, o.reject}, {0.9, 0.1}, {0.95, 0.05}, {0.98, 0.02}, {0.99, 0.01}};
  for (std::size_t k = 0; k < sweep.size(); ++k) {
    if (k > 0 && sweep[k] == sweep[0]) continue;
    const auto [acc, rej] = sweep[k];
    const AnswerQuality h = model_answers(held_out_p, test.labels, nullptr, acc, rej);
    std::printf("| model answers at --accept %.2f --reject %.2f%s, all-labelled model, held-out | %s wrong of %zu answered (%s of the candidates) |\n",
                acc, rej, k == 0 ? " (given)" : "", percent(h.answered ? double(h.wrong) / double(h.answered) : 0).c_str(),
                h.answered, percent(h.total ? double(h.answered) / double(h.total) : 0).c_str());
    if (!rest_p.empty()) {
      const AnswerQuality a = model_answers(rest_p, pool.labels, &trained_on, acc, rej);
      std::printf("| model answers at --accept %.2f --reject %.2f, active model, pool not asked | %s wrong of %zu answered (%s of the candidates) |\n",
                  acc, rej, percent(a.answered ? double(a.wrong) / double(a.answered) : 0).c_str(), a.answered,
                  percent(a.total ? double(a.answered) / double(a.total) : 0).c_str());
    }
  }
}

// Review: planted flips, found by suspicion (a model trained on the set itself, and out of fold).
void print_review(const LabelerBenchOptions& o, const Pool& pool, const LoopTrainingParams& params) {
  const std::size_t n = pool.labels.size();
  const std::size_t flips = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(o.flip_fraction * static_cast<double>(n))));
  std::vector<int> flipped = pool.labels;
  std::vector<bool> is_flip(n, false);
  for (std::size_t i : seeded_subset(n, flips, o.seed + 7)) {
    flipped[i] = 1 - flipped[i];
    is_flip[i] = true;
  }
  auto found_in_first = [&](const std::vector<double>& p, double share) {
    std::vector<double> doubt(n);
    for (std::size_t i = 0; i < n; ++i) doubt[i] = suspicion(flipped[i], p[i]);
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return doubt[a] > doubt[b]; });
    const auto shown = static_cast<std::size_t>(std::ceil(share * static_cast<double>(n)));
    std::size_t found = 0;
    for (std::size_t k = 0; k < shown; ++k) found += is_flip[order[k]] ? 1 : 0;
    return found;
  };
  std::vector<std::size_t> all_rows(n);
  for (std::size_t i = 0; i < n; ++i) all_rows[i] = i;
  const Pool flipped_pool = subset(pool, all_rows, &flipped);
  const std::optional<BoostedModel> in_sample = train_loop_model(flipped_pool.rows, flipped, flipped_pool.origins, FeatureSpec{}, params);
  const std::vector<double> oof = out_of_fold_probabilities(pool.rows, flipped, pool.origins, FeatureSpec{}, params, 5);
  if (in_sample) {
    const std::size_t found = found_in_first(probabilities(*in_sample, pool.rows), 0.05);
    std::printf("| review, model trained on the set itself: planted flips in the first 5%% shown | %zu of %zu (%s) |\n",
                found, flips, percent(double(found) / double(flips)).c_str());
  }
  const std::size_t found_oof = found_in_first(oof, 0.05);
  std::printf("| review, out-of-fold model (5 folds by group): planted flips in the first 5%% shown | %zu of %zu (%s) |\n",
              found_oof, flips, percent(double(found_oof) / double(flips)).c_str());
}

// The held-out TAR after each batch of answers, active and passive.
void print_curves(const LoopResult& active, const LoopResult& passive) {
  std::printf("\nactive-learning curve (answers: held-out TAR): ");
  for (const auto& [a, t] : active.curve) std::printf("%zu:%.3f ", a, t);
  std::printf("\npassive curve: ");
  for (const auto& [a, t] : passive.curve) std::printf("%zu:%.3f ", a, t);
  std::printf("\n");
}

}  // namespace

int run_labeler_bench(const LabelerBenchOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const FrameAnalyser analyser{AnalyserParams{}};
  const Pool pool = load(o.train, analyser);
  const Pool test = load(o.test, analyser);
  LoopTrainingParams params;
  params.boost.threads = o.threads;
  params.boost.seed = o.seed;

  const std::optional<BoostedModel> all = train_loop_model(pool.rows, pool.labels, pool.origins, FeatureSpec{}, params);
  if (!all) throw Error("the --train recordings give too few persons or not-persons to train on");
  const double target = tar_at_fppf(*all, test, 0.1);
  std::fprintf(stderr, "rdsf-labeler-bench: all-labelled model: held-out TAR %.3f at FPPF <= 0.1\n", target);
  const LoopResult active = run_loop(pool, test, target, o, true, params);
  std::fprintf(stderr, "rdsf-labeler-bench: active: %zu answers (TAR %.3f)\n", active.answers, active.tar);
  const LoopResult passive = run_loop(pool, test, target, o, false, params);
  std::fprintf(stderr, "rdsf-labeler-bench: passive: %zu answers (TAR %.3f)\n", passive.answers, passive.tar);

  print_loops(pool, test, target, active, passive);
  print_model_answers(o, *all, pool, test, active);
  print_review(o, pool, params);
  print_curves(active, passive);
  std::fprintf(stderr, "rdsf-labeler-bench: %.0f s\n",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return 0;
}

}  // namespace rdsf::bench
