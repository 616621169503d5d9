#pragma once
// rdsf-mine's work: mine negatives from frame sources into a sample set, or merge sample sets.
#include <string>
#include <vector>

#include "rdsf/dataset/negative_miner.hpp"
#include "rdsf/pipeline/stated_options.hpp"

namespace rdsf {

struct MineOptions {
  MineParams mine;                  ///< sources, stride, shard, limits, camera, detector
  std::string out;                  ///< the sample set folder (created when absent)
  std::string shard = "1/1";        ///< --shard i/n, parsed into mine.shard_index / shard_count
  std::string model;                ///< hard-negative mode: model file or name
  GivenOptions given;               ///< the analyser options given: the model's stated ones fill the rest
  std::string models_dir = "models";
  double min_score = 0;
  bool min_score_given = false;     ///< --min-score was on the command line
  std::vector<std::string> merge;   ///< merge mode: the input sets
};

/// Parses "i/n" into shard index and count; throws cli::UsageError on anything else.
void parse_shard(const std::string& text, MineParams& params);

/// Returns the process exit code.
int run_mine(MineOptions& options);
int run_merge(const MineOptions& options);

}  // namespace rdsf
