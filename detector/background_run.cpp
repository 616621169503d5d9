#include "detector/background_run.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <set>

#include "cli/progress.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/segmentation/background_model.hpp"

namespace rdsf {
namespace {

/// The frames to learn from: `count` spread evenly over a source of known length, else its first `count`.
std::set<std::int64_t> frames_to_learn(const FrameSource& source, std::int64_t count) {
  std::set<std::int64_t> chosen;
  if (const auto total = source.frame_count()) {
    for (std::int64_t i : evenly_spaced(*total, count)) chosen.insert(i);
  } else {
    for (std::int64_t i = 0; i < count; ++i) chosen.insert(i);
  }
  return chosen;
}

/// The share of the learned frames' readings in front of the background (foreground_mask with the
/// default margins): near 0 for a static camera and an empty room, large when the camera moved.
double foreground_share(const BackgroundLearner& learner, const BackgroundModel& model) {
  double front = 0, readings = 0;
  for (const cv::Mat1w& depth_mm : learner.depths_mm()) {
    front += cv::countNonZero(foreground_mask(depth_mm, model.far_mm, BackgroundParams{}));
    readings += cv::countNonZero(depth_mm);
  }
  return readings > 0 ? front / readings : 0.0;
}

}  // namespace

int run_background(const BackgroundOptions& o) {
  auto source = open_frame_source(o.source, o.frame_options);
  const std::set<std::int64_t> chosen = frames_to_learn(*source, o.frames);
  const std::int64_t last = chosen.empty() ? -1 : *chosen.rbegin();
  BackgroundLearner learner(o.quantile);
  cli::Progress progress(std::cerr, "frames", last + 1);
  DepthFrame frame;
  for (std::int64_t i = 0; i <= last && source->next(frame); ++i) {
    if (chosen.count(i) != 0) learner.add(frame);
    progress.update(i + 1);
  }
  progress.finish(last + 1);
  BackgroundModel model = learner.model();
  write_background(o.out, model, o.force);
  const double share = foreground_share(learner, model);
  std::fprintf(stderr,
               "rdsf-background: learned from %zu frames of %s (quantile %.2f); %.1f %% of their readings lie in "
               "front of it (measured: a static camera over an empty room 0.1-6 %%, with people in it up to about 22 %%; "
               "a moving camera 17-58 %%, docs/candidates.md)\n"
               "rdsf-background: wrote %s\n",
               learner.frames(), source->description().c_str(), o.quantile, 100.0 * share, o.out.c_str());
  return 0;
}

}  // namespace rdsf
