#pragma once
// The adaptation benchmark's picture (scripts/adaptation-benchmark.sh): answers spent against TAR at
// FPPF <= 0.1, one curve per mode (none, negatives, candidate, track), each point the mean over the rooms of
// one budget. Drawn with evaluation/curve_plot.
#include <string>

namespace rdsf {

/// Reads the benchmark's results.tsv (room, mode, budget, answers, propagated, propagated_wrong, tar,
/// train_s) and writes the chart to `png`. Throws Error naming the file and line on a bad row.
void write_adaptation_chart(const std::string& results_tsv, const std::string& png);

}  // namespace rdsf
