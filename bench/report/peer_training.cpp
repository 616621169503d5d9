#include "peer_training.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "rdsf/classifier/binned_matrix.hpp"
#include "rdsf/classifier/parallel_chunks.hpp"
#include "rdsf/classifier/real_adaboost.hpp"
#include "rdsf/classifier/roc_metrics.hpp"
#include "speed_limits.hpp"
#include "report_clock.hpp"
#include "training_crops.hpp"

namespace rdsf::perf {
namespace {

using clock::Clock;
using clock::seconds_since;

void say(const std::string& text) { std::cerr << "peers: " << text << std::endl; }

void write_bins(const std::filesystem::path& dir, const std::string& name, const BinnedMatrix& m,
                const std::vector<int>& labels) {
  std::ofstream bins(dir / (name + ".bins"), std::ios::binary);
  for (std::size_t f = 0; f < m.features(); ++f) {
    bins.write(reinterpret_cast<const char*>(m.feature(f)), static_cast<std::streamsize>(m.samples()));
  }
  std::ofstream out(dir / (name + ".labels"), std::ios::binary);
  for (int l : labels) out.put(static_cast<char>(l));
}

PeerCurve native_curve(const BinnedMatrix& binned, const std::vector<int>& labels, const TrainingRows& held_out,
                       int depth, const PeerOptions& o, bool subtraction = false) {
  PeerCurve c;
  c.name = "native Real AdaBoost, depth " + std::to_string(depth) + (subtraction ? ", histogram subtraction" : "");
  c.ran = true;
  RealAdaBoostParams params;
  params.threads = o.threads;
  params.depth = depth;
  params.histogram_subtraction = subtraction;
  RealAdaBoost booster(binned, labels, params);
  std::vector<double> scores(held_out.labels.size(), 0.0);
  const BinScheme& bins = binned.scheme();
  double training = 0, cpu = 0;
  for (int r = 0; r < o.max_rounds && training < o.budget_s; ++r) {
    const Clock::time_point t = Clock::now();
    const double cpu0 = clock::process_cpu_seconds();
    booster.next_round();
    training += seconds_since(t);
    cpu += clock::process_cpu_seconds() - cpu0;
    const WeakClassifier& weak = booster.weak_classifiers().back();
    for (std::size_t i = 0; i < scores.size(); ++i) scores[i] += weak.respond_row(held_out.rows[static_cast<int>(i)], bins);
    c.time_s.push_back(training);
    c.auc.push_back(roc_auc(scores, held_out.labels));
  }
  c.cpu_s_per_round = c.time_s.empty() ? 0 : cpu / static_cast<double>(c.time_s.size());
  return c;
}

PeerCurve xgboost_curve(const std::filesystem::path& dir, int depth, const PeerOptions& o) {
  PeerCurve c;
  c.name = "XGBoost hist, depth " + std::to_string(depth);
  std::string python = o.python;
  if (python.empty()) python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string script = std::string(RDSF_REPORT_SCRIPT_DIR) + "/xgboost_peer.py";
  const std::string command = python + " " + script + " " + dir.string() + " " + std::to_string(depth) + " " +
                              std::to_string(o.threads) + " " + clock::fixed(o.budget_s, 2) + " " +
                              std::to_string(o.max_rounds) + " 2>" + (dir / "xgboost.err").string();
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) {
    c.note = "cannot start " + python;
    return c;
  }
  char line[256];
  while (std::fgets(line, sizeof line, pipe) != nullptr) {
    int round = 0;
    double t = 0, auc = 0;
    if (std::sscanf(line, "setup %lf", &t) == 1) {
      c.setup_s = t;
    } else if (std::sscanf(line, "%d %lf %lf", &round, &t, &auc) == 3) {
      c.time_s.push_back(t);
      c.auc.push_back(auc);
    }
  }
  const int status = ::pclose(pipe);
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 3 || code == 127) {  // the script's "cannot import", or no interpreter at all
    c.note = "not installed (" + python + " with python3-xgboost and python3-numpy): skipped";
  } else if (code != 0 || c.time_s.empty()) {
    std::ifstream err(dir / "xgboost.err");
    std::string last, text;
    while (std::getline(err, text)) {
      if (!text.empty()) last = text;
    }
    c.note = "failed (exit " + std::to_string(code) + "): " + last;
  }
  c.ran = c.note.empty();
  return c;
}

// Training time when the curve first reaches `auc` (negative: never).
double time_to(const PeerCurve& c, double auc) {
  for (std::size_t k = 0; k < c.auc.size(); ++k) {
    if (c.auc[k] >= auc) return c.time_s[k];
  }
  return -1;
}

// Held-out AUC of the last round finished within `seconds` (negative when none).
double auc_at(const PeerCurve& c, double seconds) {
  double a = -1;
  for (std::size_t k = 0; k < c.auc.size() && c.time_s[k] <= seconds; ++k) a = c.auc[k];
  return a;
}

// One weighted update per sample and feature, written plainly (PeerResults::scatter_s).
double scatter_add_seconds(const BinnedMatrix& binned, int threads) {
  const std::size_t n = binned.samples();
  const std::vector<double> w(n, 1.0 / static_cast<double>(std::max<std::size_t>(1, n)));
  std::vector<double> sink(binned.features(), 0.0);
  double best = 1e30;
  for (int pass = 0; pass < 3; ++pass) {
    const auto start = std::chrono::steady_clock::now();
    parallel_chunks(binned.features(), threads, [&](std::size_t begin, std::size_t end) {
      for (std::size_t f = begin; f < end; ++f) {
        double h[4][256] = {};
        const std::uint8_t* b = binned.feature(f);
        std::size_t i = 0;
        for (; i + 4 <= n; i += 4) {
          h[0][b[i]] += w[i];
          h[1][b[i + 1]] += w[i + 1];
          h[2][b[i + 2]] += w[i + 2];
          h[3][b[i + 3]] += w[i + 3];
        }
        for (; i < n; ++i) h[0][b[i]] += w[i];
        sink[f] = h[0][b[0]] + h[1][b[0]] + h[2][b[0]] + h[3][b[0]];
      }
    });
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  volatile double keep = sink.empty() ? 0.0 : sink[0];
  (void)keep;
  return best;
}

double per_round(const PeerCurve& c) { return c.time_s.empty() ? 0 : c.time_s.back() / static_cast<double>(c.time_s.size()); }

}  // namespace

PeerResults measure_peers(const PeerOptions& o) {
  PeerResults r;
  r.options = o;
  r.threads = o.threads;
  r.load_start = clock::load_average_now();
  say("training rows " + std::to_string(o.positives) + " + " + std::to_string(o.negatives) +
      " (the report's generator and seeds) and 20 % held out");
  const TrainingRows train = make_training_rows(o.positives, o.negatives, 1);
  const TrainingRows held_out = make_training_rows(o.positives / 5, o.negatives / 5, 2);
  r.train_rows = train.rows.rows;
  r.held_out_rows = held_out.rows.rows;
  r.features = train.rows.cols;
  const BinnedRows positives_first = bin_positives_first(train, o.threads);
  const BinnedMatrix& binned = positives_first.matrix;
  const std::vector<int>& labels = positives_first.labels;
  r.binning_s = positives_first.seconds;
  r.bins_mb = static_cast<double>(binned.samples()) * static_cast<double>(binned.features()) / 1e6;
  say("memory bandwidth on " + std::to_string(o.threads) + " threads");
  r.read_gbps_n = read_bandwidth_gbps(o.quick ? 256 : 1024, o.threads, 3);
  say("plain scatter-add: one weighted histogram update per bin on " + std::to_string(o.threads) + " threads");
  r.scatter_s = scatter_add_seconds(binned, o.threads);

  for (const int depth : {1, 2, 3}) {
    say("native depth " + std::to_string(depth) + ": up to " + clock::fixed(o.budget_s, 1) + " s of training");
    r.curves.push_back(native_curve(binned, labels, held_out, depth, o));
  }
  say("native depth 3 with histogram subtraction: up to " + clock::fixed(o.budget_s, 1) + " s of training");
  r.curves.push_back(native_curve(binned, labels, held_out, 3, o, true));

  const auto dir = std::filesystem::temp_directory_path() / ("rdsf-peers-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  say("XGBoost: the same bins written to " + dir.string());
  write_bins(dir, "train", binned, labels);
  const BinnedMatrix held_out_bins(held_out.rows, binned.scheme(), {}, o.threads);
  write_bins(dir, "held_out", held_out_bins, held_out.labels);
  std::ofstream(dir / "features") << binned.features();
  for (const int depth : {1, 3}) {
    say("XGBoost depth " + std::to_string(depth) + ": up to " + clock::fixed(o.budget_s, 1) + " s of training");
    r.curves.push_back(xgboost_curve(dir, depth, o));
    if (!r.curves.back().ran) {
      say(r.curves.back().note);
      if (r.curves.back().note.rfind("not installed", 0) == 0) {
        r.curves.push_back(r.curves.back());
        r.curves.back().name = "XGBoost hist, depth 3";
        break;
      }
    }
  }
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  r.load_end = clock::load_average_now();
  return r;
}

std::string peers_markdown(const PeerResults& r) {
  std::ostringstream m;
  // The target AUC: the best any XGBoost run reached, else the native depth-1 final.
  double target = 0, equal_time = 1e300;
  bool xgboost_ran = false;
  for (const PeerCurve& c : r.curves) {
    if (!c.ran || c.auc.empty()) continue;
    equal_time = std::min(equal_time, c.time_s.back());  // every trainer trained at least this long
    if (c.name.rfind("XGBoost", 0) == 0) {
      xgboost_ran = true;
      target = std::max(target, *std::max_element(c.auc.begin(), c.auc.end()));
    }
  }
  if (!xgboost_ran && !r.curves.empty() && !r.curves[0].auc.empty()) target = r.curves[0].auc.back();
  m << "\n#### Trainers side by side (issue 17)\n\n"
    << r.train_rows << " training rows x " << r.features << " RDSF features (the report's generated crops, the "
    << "same generator and seeds as the training comparison above) and " << r.held_out_rows
    << " held-out rows; every trainer sees the same 64-bin quantisation (" << clock::fixed(r.bins_mb, 0)
    << " MB of 8-bit bins, binned in " << clock::fixed(r.binning_s, 2) << " s, not counted below; XGBoost reads the bins "
    << "as values into its QuantileDMatrix with max_bin 64, built before its rounds and not counted either). " << r.threads
    << " threads each, up to " << clock::fixed(r.options.budget_s, 1) << " s of training or " << r.options.max_rounds
    << " rounds; held-out scoring after every round is not counted. Load average " << r.load_start << " at the start, "
    << r.load_end << " at the end.\n\n"
    << "| Trainer | Rounds | Time per round | Held-out AUC at the end | Time to AUC " << clock::fixed(target, 4)
    << " | AUC after " << clock::fixed(equal_time, 2) << " s |\n|---|---|---|---|---|---|\n";
  for (const PeerCurve& c : r.curves) {
    if (!c.ran) {
      m << "| " << c.name << " | - | " << c.note << " | - | - | - |\n";
      continue;
    }
    const double to = time_to(c, target);
    m << "| " << c.name << " | " << c.auc.size() << " | " << clock::fixed(per_round(c), 3) << " s";
    if (c.cpu_s_per_round > 0) m << " (processor " << clock::fixed(c.cpu_s_per_round, 3) << " s)";
    if (c.setup_s > 0) m << " (after " << clock::fixed(c.setup_s, 1) << " s building its quantised matrix)";
    m << " | " << clock::fixed(c.auc.back(), 4) << " | " << (to < 0 ? std::string("not reached") : clock::fixed(to, 2) + " s") << " | "
      << (auc_at(c, equal_time) < 0 ? std::string("no round yet") : clock::fixed(auc_at(c, equal_time), 4)) << " |\n";
  }
  if (r.options.opencv_ran) {
    m << "| OpenCV cv::ml::Boost REAL stumps (the comparison above) | " << r.options.opencv_rounds << " | "
      << clock::fixed(r.options.opencv_s_per_round, 2) << " s | " << clock::fixed(r.options.opencv_auc, 4) << " | "
      << (r.options.opencv_auc >= target ? std::string("-") : std::string("not reached")) << " | - |\n";
  }
  // The native rounds against the streaming time of their bins, and the cost per tree level.
  if (!r.curves.empty() && r.curves[0].ran && r.read_gbps_n > 0) {
    const double stream_s = r.bins_mb * 1e6 / (r.read_gbps_n * 1e9);
    const double d1 = per_round(r.curves[0]);
    m << "\nNative round against the machine: streaming its " << clock::fixed(r.bins_mb, 0) << " MB of bins at the "
      << clock::fixed(r.read_gbps_n, 1) << " GB/s measured now on " << r.threads << " threads takes " << clock::fixed(1e3 * stream_s, 1)
      << " ms; a depth-1 round took " << clock::fixed(1e3 * d1, 1) << " ms = " << clock::fixed(d1 / stream_s, 2)
      << "x that (target 1.5x).";
    if (r.scatter_s > 0) {
      // 1.5x the streaming time means this many table updates per second on each thread.
      const double needed = r.bins_mb * 1e6 / (1.5 * stream_s) / r.threads / 1e9;
      m << " A histogram round does not stream, though: each byte of bins is a load, add and store of a table "
        << "entry. 1.5x the streaming time would take " << clock::fixed(needed, 1) << " billion such updates per "
        << "second on each thread; a plain weighted scatter-add over the same bins (four tables, no class split, no "
        << "fixed order) does " << clock::fixed(r.bins_mb * 1e6 / r.scatter_s / r.threads / 1e9, 2)
        << " billion (" << clock::fixed(1e3 * r.scatter_s, 1) << " ms for all of them on " << r.threads
        << " threads), and the depth-1 round, with its class split and fixed order, takes "
        << clock::fixed(d1 / r.scatter_s, 2) << "x that time.";
    }
    for (std::size_t k = 1; k < r.curves.size() && k < 4; ++k) {
      if (!r.curves[k].ran) continue;
      const double levels = k < 3 ? static_cast<double>(k + 1) : 3.0;  // [3]: depth 3 with subtraction
      m << (k < 3 ? " Depth " + std::to_string(k + 1) : std::string(" Depth 3 with histogram subtraction")) << ": "
        << clock::fixed(1e3 * per_round(r.curves[k]) / levels, 1) << " ms per tree level ("
        << clock::fixed(per_round(r.curves[k]) / levels / d1, 2) << "x depth 1's).";
    }
    m << "\n";
  }
  return m.str();
}

std::string peers_summary(const PeerResults& r) {
  std::ostringstream m;
  for (const PeerCurve& c : r.curves) {
    m << "  " << c.name << ": ";
    if (!c.ran) {
      m << c.note << "\n";
      continue;
    }
    m << c.auc.size() << " rounds, " << clock::fixed(per_round(c), 3) << " s per round, held-out AUC " << clock::fixed(c.auc.back(), 4)
      << "\n";
  }
  return m.str();
}

}  // namespace rdsf::perf
