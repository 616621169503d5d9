#pragma once
// rdsf-review's work: a window (or a --keys file) in front of a ReviewSession.
#include <string>

#include "rdsf/labeling/review_session.hpp"

namespace rdsf {

struct ReviewOptions {
  std::string set;
  std::string model;               ///< empty: no model
  std::string models_dir = "models";
  std::string sort;                ///< empty: suspicion with a model, else origin
  int columns = 6, rows = 2;
  int folds = 0;                   ///< without a model: out-of-fold P from this many in-process models
  long list = 0;                   ///< print the first N samples of the order (id, label, P, origin) first
  std::string keys;                ///< empty: window; "-": stdin; else a file
};

int run_review(const ReviewOptions& options);

}  // namespace rdsf
