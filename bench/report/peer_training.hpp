#pragma once
// Trainers side by side on the same hugeTree-size matrix and the same held-out rows (issue 17): the native
// Real AdaBoost at depths 1, 2 and 3 (and 3 with histogram subtraction), and XGBoost (tree_method=hist, depth 1 and 3, through
// bench/report/xgboost_peer.py and Debian's python3-xgboost; skipped with a note when it is not
// installed), each trained until a time budget or a round limit, with the held-out AUC after every round.
// OpenCV's cv::ml::Boost is the report's own training comparison (same matrix, same rows), shown beside.
// The native rounds are also set against the streaming time of their bins at the bandwidth measured in
// the same run, and against a plain weighted scatter-add over the same bins on the same threads (h[bin] +=
// w per sample and feature, four tables so that equal bins in a row wait less for each other, no class
// split and no fixed order): the update rate a round's table updates run at, which streaming does not bound.
#include <string>
#include <vector>

namespace rdsf::perf {

struct PeerOptions {
  bool quick = false;
  int threads = 2;
  int positives = 5628, negatives = 22454;  ///< the report's training rows (same generator and seeds)
  double budget_s = 20;                     ///< training time per trainer (quick: 2)
  int max_rounds = 200;
  std::string python;  ///< interpreter for xgboost_peer.py; empty: /usr/bin/python3, else python3
  // OpenCV's figures from the report's training comparison (same matrix), when it ran
  bool opencv_ran = false;
  int opencv_rounds = 0;
  double opencv_s_per_round = 0, opencv_auc = 0;
};

struct PeerCurve {
  std::string name;
  bool ran = false;
  std::string note;            ///< why it did not run
  std::vector<double> time_s;  ///< training time after each round (held-out scoring not counted)
  std::vector<double> auc;     ///< held-out AUC after each round
  double cpu_s_per_round = 0;  ///< native only: processor time per round
  double setup_s = 0;          ///< XGBoost only: building its quantised matrix (before the rounds)
};

struct PeerResults {
  int threads = 2, train_rows = 0, held_out_rows = 0, features = 0;
  double bins_mb = 0, binning_s = 0, read_gbps_n = 0;
  double scatter_s = 0;  ///< the plain scatter-add over every bin once (best of 3)
  std::vector<PeerCurve> curves;
  PeerOptions options;
  std::string load_start, load_end;
};

PeerResults measure_peers(const PeerOptions& options);

std::string peers_markdown(const PeerResults& r);
std::string peers_summary(const PeerResults& r);

}  // namespace rdsf::perf
