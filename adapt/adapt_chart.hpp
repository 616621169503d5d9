#pragma once
// The adaptation benchmark's picture (scripts/adaptation-benchmark.sh): its results.tsv drawn by
// rdsf/evaluation/adaptation_results.hpp (answers spent against TAR at FPPF <= 0.1, one curve per mode).
#include <string>

namespace rdsf {

/// Reads the benchmark's results.tsv and writes the chart to `png`. Throws Error naming the file and line
/// on a bad row.
void write_adaptation_chart(const std::string& results_tsv, const std::string& png);

}  // namespace rdsf
