#pragma once
// The labeler's benchmark, with ground truth as the oracle (the "person" who answers), on labelled
// recordings (rdsf-synth's boxes.csv):
//   pool     every candidate of the --train recordings whose answer the truth is sure of (the reported box
//            overlaps a counted person with IoU >= 0.5: person; < 0.3 with everyone: not a person; the
//            band between and don't-care people are left out, as the labeler's assisted mode does);
//   held-out the candidates of the --test recordings, labelled the same way;
//   TAR      at FPPF <= 0.1, over the held-out candidates: the threshold is the lowest score at which at
//            most 0.1 x frames not-person candidates score above it; TAR = share of persons above it
//            (candidate level: no grouping of overlapping candidates, no matching);
//   1. the all-labelled model: trained on the whole pool (the loop's trainer, active_learning.hpp); its
//      held-out TAR is the target;
//   2. active learning: a seeded random first batch, then batch after batch the pool's most uncertain
//      candidates under the model trained on the answers so far (every explore-th a random one, as
//      rdsf-label --loop); answers needed to reach the target;
//      the same with random batches (passive) for comparison;
//   3. model answers: the share of wrong answers and of candidates answered at --accept / --reject (and a
//      sweep), by the all-labelled model on the held-out candidates and by the active model on the pool
//      candidates it was not trained on;
//   4. review: 1% of the pool's labels flipped (seeded); samples sorted by suspicion under a model trained
//      on the flipped labels (out of fold: 5 folds by group; and in-sample, as rdsf-review with a model
//      trained on the set itself); share of the flips among the first 5% shown.
#include <cstdint>
#include <string>
#include <vector>

namespace rdsf::bench {

struct LabelerBenchOptions {
  std::vector<std::string> train, test;  ///< synthetic recordings with boxes.csv
  int batch = 25;                        ///< answers per batch
  int explore = 5;                       ///< active: every explore-th answer a random candidate (0: off)
  double accept = 0.99, reject = 0.01;   ///< the model answers measured
  double flip_fraction = 0.01;           ///< review: labels flipped
  std::uint64_t seed = 1;
  int threads = 0;
};

/// Runs the benchmark and prints a Markdown table to stdout (progress on stderr). Returns 0.
int run_labeler_bench(const LabelerBenchOptions& options);

}  // namespace rdsf::bench
