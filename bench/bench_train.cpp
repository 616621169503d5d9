// Training speed at hugeTree size: the native Real AdaBoost trainer against OpenCV's cv::ml::Boost (REAL,
// stumps) on the same feature matrix, in one run on the same machine.
//
// Data: real RDSF vectors (RdsfExtractor) of generated 64x128 masked depth crops. Positives are a
// person-like silhouette (head, torso, swinging arms, legs) at a random depth, scale and offset, with
// noise, missing readings, partial occlusion and clutter from the same layer; negatives are clutter
// (boxes, poles, chair- and table-like shapes, wall pieces, blobs), some of it person-sized. 28,082
// training rows (5,628 positives, 22,454 negatives, as the thesis's hugeTree) plus a separate validation
// set of 20 % of that size.
//
// OpenCV trains all its rounds in one call without progress, so it is timed at two round counts (1 and 3
// by default) and its cost per round is the difference divided by the extra rounds (its fixed set-up cost
// cancels out); the time for N rounds is extrapolated linearly from that. Validation AUCs are compared at
// the rounds OpenCV ran, and the native AUC after all its rounds is reported too.
//
// Options (before Google Benchmark's own): --positives=N --negatives=N --native-rounds=N
// --opencv-rounds=A,B (0,0 skips OpenCV) --threads=N --feature-spec=rdsf|rdsf-rect[:...] --feature-pool=N
// (a seeded pool of N of the spec's features, as rdsf-train --feature-pool; 0 = all) --depth=N (native
// trees, 1..4) --subtraction=1 (native histogram subtraction) --weight-trim=X.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <string>

#include <opencv2/imgproc.hpp>

#include "rdsf/classifier/binned_matrix.hpp"
#include "rdsf/classifier/boost_training.hpp"
#include "rdsf/classifier/opencv_boost.hpp"
#include "rdsf/classifier/real_adaboost.hpp"
#include "rdsf/classifier/roc_metrics.hpp"
#include "rdsf/classifier/seeded_sampling.hpp"
#include "rdsf/features/rdsf_extractor.hpp"
#include "report/training_crops.hpp"

namespace {

using Clock = std::chrono::steady_clock;

struct Config {
  int positives = 5628, negatives = 22454;
  int native_rounds = 100;
  int opencv_a = 1, opencv_b = 3;
  int threads = 0;
  std::string spec = "rdsf";
  std::size_t pool = 0;
  int depth = 1;
  bool subtraction = false;
  double weight_trim = 0.0;
} config;

std::vector<int> pool_columns() {
  const rdsf::FeatureSpec spec = rdsf::FeatureSpec::parse(config.spec);
  std::vector<int> columns;
  if (config.pool == 0 || config.pool >= static_cast<std::size_t>(spec.dimension())) return columns;
  for (std::size_t f : rdsf::seeded_subset(static_cast<std::size_t>(spec.dimension()), config.pool, 1)) {
    columns.push_back(static_cast<int>(f));
  }
  return columns;
}

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double peak_rss_mib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  }
  return 0.0;
}

// Crops and their RDSF rows come from report/training_crops (shared with the performance report, so both
// train on the same kind of data).

struct Data {
  cv::Mat1f train, validation;
  std::vector<int> train_labels, validation_labels;
  double generate_s = 0.0;
};

void make_rows(int positives, int negatives, std::uint64_t seed, cv::Mat1f& rows, std::vector<int>& labels) {
  static const std::vector<int> columns = pool_columns();
  rdsf::perf::TrainingRows made = rdsf::perf::make_training_rows(positives, negatives, seed,
                                                                 rdsf::FeatureSpec::parse(config.spec), columns);
  rows = made.rows;
  labels = std::move(made.labels);
}

Data& data() {
  static Data d = [] {
    Data out;
    const Clock::time_point start = Clock::now();
    make_rows(config.positives, config.negatives, 1, out.train, out.train_labels);
    make_rows(config.positives / 5, config.negatives / 5, 2, out.validation, out.validation_labels);
    out.generate_s = seconds_since(start);
    std::fprintf(stderr, "bench_train: %d + %d training rows, %d validation rows of %d features generated in %.1f s\n",
                 config.positives, config.negatives, out.validation.rows, out.train.cols, out.generate_s);
    return out;
  }();
  return d;
}

// Validation AUC of the first `rounds` weak classifiers.
double validation_auc(const std::vector<rdsf::WeakClassifier>& weak, std::size_t rounds, const rdsf::BinScheme& bins) {
  std::vector<double> scores(data().validation_labels.size(), 0.0);
  for (std::size_t k = 0; k < std::min(rounds, weak.size()); ++k) {
    for (std::size_t i = 0; i < scores.size(); ++i) {
      scores[i] += weak[k].respond_row(data().validation[static_cast<int>(i)], bins);
    }
  }
  return rdsf::roc_auc(scores, data().validation_labels);
}

struct Results {
  double native_s_per_round = 0, native_total_s = 0, native_bin_s = 0, native_peak_mib = 0;
  std::vector<rdsf::WeakClassifier> native_weak;
  double opencv_a_s = 0, opencv_b_s = 0;
  std::vector<rdsf::WeakClassifier> opencv_weak;
  double opencv_peak_mib = 0;
} results;

void BM_NativeRealAdaBoost(benchmark::State& state) {
  Data& d = data();
  for (auto _ : state) {
    const Clock::time_point start = Clock::now();
    const std::vector<std::size_t> order = rdsf::positives_first_order(d.train_labels);
    const rdsf::BinnedMatrix binned(d.train, rdsf::BinScheme{}, order, config.threads);
    std::vector<int> labels;
    for (std::size_t i : order) labels.push_back(d.train_labels[i]);
    results.native_bin_s = seconds_since(start);
    rdsf::RealAdaBoostParams params;
    params.threads = config.threads;
    params.depth = config.depth;
    params.histogram_subtraction = config.subtraction;
    params.weight_trim = config.weight_trim;
    rdsf::RealAdaBoost booster(binned, labels, params);
    const Clock::time_point rounds_start = Clock::now();
    for (int r = 0; r < config.native_rounds; ++r) booster.next_round();
    const double rounds_s = seconds_since(rounds_start);
    results.native_total_s = seconds_since(start);
    results.native_s_per_round = rounds_s / config.native_rounds;
    results.native_weak = booster.weak_classifiers();
    state.SetIterationTime(results.native_total_s);
  }
  results.native_peak_mib = peak_rss_mib();
  state.counters["rounds"] = config.native_rounds;
  state.counters["s_per_round"] = results.native_s_per_round;
  state.counters["binning_s"] = results.native_bin_s;
  state.counters["val_auc"] = validation_auc(results.native_weak, results.native_weak.size(), rdsf::BinScheme{});
  state.counters["peak_rss_MiB"] = results.native_peak_mib;
}

void BM_OpenCvBoost(benchmark::State& state) {
  Data& d = data();
  const int rounds = static_cast<int>(state.range(0));
  double seconds = 0;
  for (auto _ : state) {
    const Clock::time_point start = Clock::now();
    rdsf::OpenCvBoostParams params;
    params.rounds = rounds;
    const rdsf::OpenCvBoostResult result = rdsf::train_opencv_boost(d.train, d.train_labels, params);
    seconds = seconds_since(start);
    state.SetIterationTime(seconds);
    if (rounds == config.opencv_b) results.opencv_weak = result.stumps;
  }
  (rounds == config.opencv_a ? results.opencv_a_s : results.opencv_b_s) = seconds;
  results.opencv_peak_mib = peak_rss_mib();
  state.counters["rounds"] = rounds;
  state.counters["peak_rss_MiB"] = results.opencv_peak_mib;
}

void parse_own_flags(int& argc, char** argv) {
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> const char* {
      const std::size_t n = std::strlen(name);
      return a.compare(0, n, name) == 0 ? a.c_str() + n : nullptr;
    };
    if (const char* v = value("--positives=")) config.positives = std::atoi(v);
    else if (const char* v2 = value("--negatives=")) config.negatives = std::atoi(v2);
    else if (const char* v3 = value("--native-rounds=")) config.native_rounds = std::atoi(v3);
    else if (const char* v4 = value("--threads=")) config.threads = std::atoi(v4);
    else if (const char* v5 = value("--opencv-rounds=")) std::sscanf(v5, "%d,%d", &config.opencv_a, &config.opencv_b);
    else if (const char* v6 = value("--feature-spec=")) config.spec = v6;
    else if (const char* v7 = value("--feature-pool=")) config.pool = static_cast<std::size_t>(std::atoll(v7));
    else if (const char* v8 = value("--depth=")) config.depth = std::atoi(v8);
    else if (const char* v9 = value("--subtraction=")) config.subtraction = std::atoi(v9) != 0;
    else if (const char* v10 = value("--weight-trim=")) config.weight_trim = std::atof(v10);
    else argv[kept++] = argv[i];
  }
  argc = kept;
}

}  // namespace

int main(int argc, char** argv) {
  parse_own_flags(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RegisterBenchmark("native_real_adaboost", BM_NativeRealAdaBoost)
      ->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
  const bool opencv = config.opencv_b > config.opencv_a && config.opencv_a > 0;
  if (opencv) {
    benchmark::RegisterBenchmark("opencv_boost_real_stumps", BM_OpenCvBoost)
        ->Arg(config.opencv_a)->Arg(config.opencv_b)->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();

  const rdsf::BinScheme bins;
  std::printf("\nSummary (%d x %d training rows, %d validation rows):\n", data().train.rows, data().train.cols,
              data().validation.rows);
  std::printf("  native: %d rounds in %.1f s (binning %.1f s + %.3f s per round), peak RSS %.0f MiB, validation AUC %.4f\n",
              config.native_rounds, results.native_total_s, results.native_bin_s, results.native_s_per_round,
              results.native_peak_mib, validation_auc(results.native_weak, results.native_weak.size(), bins));
  if (opencv && results.opencv_b_s > 0) {
    const double per_round = (results.opencv_b_s - results.opencv_a_s) / (config.opencv_b - config.opencv_a);
    const double setup = std::max(0.0, results.opencv_a_s - per_round * config.opencv_a);
    std::printf("  opencv: %d rounds %.1f s, %d rounds %.1f s -> %.2f s per round (difference / %d), set-up %.1f s;\n"
                "          extrapolated %d rounds: %.0f s; peak RSS %.0f MiB\n",
                config.opencv_a, results.opencv_a_s, config.opencv_b, results.opencv_b_s, per_round,
                config.opencv_b - config.opencv_a, setup, config.native_rounds, setup + per_round * config.native_rounds,
                results.opencv_peak_mib);
    std::printf("  per round: native is %.0fx faster\n", per_round / results.native_s_per_round);
    const std::size_t k = static_cast<std::size_t>(config.opencv_b);
    std::printf("  validation AUC after %zu rounds: native %.4f, opencv %.4f (difference %+.4f)\n", k,
                validation_auc(results.native_weak, k, bins), validation_auc(results.opencv_weak, k, bins),
                validation_auc(results.native_weak, k, bins) - validation_auc(results.opencv_weak, k, bins));
  }
  return 0;
}
