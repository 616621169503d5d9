#pragma once
// rdsf-label's own options (the camera's and the frame analyser's are added by main after them), and what the
// ones that are not simply a member become once parsed.
#include <string>

#include "cli/cli.hpp"
#include "labeler/label_run.hpp"

namespace rdsf {

/// The options' text before it becomes LabelOptions (apply_option_text).
struct LabelOptionText {
  bool no_model_answers = false;  ///< --no-model-answers
  std::string ask = "order";      ///< --ask order|uncertain|likely
  int explore = 5;                ///< --explore N (with --loop)
};

/// rdsf-label's options, in --help's order, writing into `o` and `text`.
cli::po::options_description label_options(LabelOptions& o, LabelOptionText& text);

/// After parsing: --no-model-answers, --ask and --loop (which implies --ask uncertain, --keep-rejected and
/// --explore) into o.session. Throws cli::UsageError for an unknown --ask.
void apply_option_text(const LabelOptionText& text, LabelOptions& o);

}  // namespace rdsf
