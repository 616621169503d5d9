#pragma once
// rdsf-train's options (what to train on, boosting parameters, --inspect / --export-text), bound to `o`.
#include "cli/cli.hpp"
#include "trainer/train_run.hpp"

namespace rdsf {

cli::po::options_description train_options(TrainOptions& o);

}  // namespace rdsf
