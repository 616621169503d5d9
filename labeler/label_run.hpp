#pragma once
// rdsf-label's work: a window (or an --answers file) in front of a LabelingSession.
#include <string>

#include "rdsf/labeling/labeling_session.hpp"
#include "rdsf/pipeline/stated_options.hpp"

namespace rdsf {

struct LabelOptions {
  LabelingConfig session;
  std::string out_set;
  std::string model;           ///< empty: no model
  GivenOptions given;          ///< the analyser options given: the model's stated ones fill the rest
  std::string models_dir = "models";
  std::string truth_csv;       ///< empty: no assisted mode
  std::string answers;         ///< empty: window; "-": stdin; else a file
 bool loop = false;           ///< active learning: batch, retrain, re-score, next batch
  int batch = 25;              ///< --loop: human answers per batch
  std::string loop_model = "loop";
  /// --loop: at its end the last model answers what it is sure of, if the person gave this many y and n
  long loop_answer_after = 30;  ///< --loop: models saved as models_dir/loop_model/vN.yml
  long budget = 0;             ///< stop after this many human answers; 0: no limit
  double min_visible = 0.5;    ///< assisted mode: people less visible than this are don't-care
  /// An analyser option (--only-added-by NAME): only the candidates it adds are asked and stored, those the
  /// same options with NAME at its default make too are left out (LabelingConfig::only_added_beyond).
  std::string only_added_by;
};

/// Checks the options together (cli::UsageError naming the option, exit 2): --accept and --reject,
/// --truth-oracle, --batch, --ask uncertain/likely, --per-track, --budget, --only-added-by's name. Call once,
/// before run_label.
void check_options(const LabelOptions& options);

int run_label(const LabelOptions& options);

}  // namespace rdsf
