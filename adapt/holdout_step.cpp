#include "adapt/holdout_step.hpp"

#include <filesystem>
#include <iostream>
#include <algorithm>
#include <optional>
#include <set>
#include <tuple>

#include "rdsf/classifier/model_registry.hpp"
#include "rdsf/dataset/sample_set.hpp"
#include "rdsf/dataset/sample_set_merge.hpp"
#include "rdsf/dataset/sample_set_writer.hpp"
#include "rdsf/frame/frame_source.hpp"
#include "rdsf/pipeline/holdout_check.hpp"

namespace rdsf {
namespace {

namespace fs = std::filesystem;

void say(const std::string& line) { std::cerr << "rdsf-adapt: check: " << line << "\n"; }

// `input`'s samples outside the frames `later` (all of them when `split` is false) copied into a set in `dir`.
std::string earlier_part(const std::string& input, const std::set<std::string>& later, bool split,
                         const std::string& dir) {
  const SampleSet set = SampleSet::open_read(input);
  const std::string out = (fs::path(dir) / ("earlier-" + fs::path(input).filename().string())).string();
  SampleSetWriter writer = SampleSetWriter::open_or_create(out, set.feature_spec(), set.manifest().camera,
                                                           "rdsf-adapt --holdout-check", set.manifest().crops,
                                                           set.manifest().analyser_options);
  merge_sample_sets({input}, writer, [&](const SampleRecord& r) { return !split || later.count(r.frame) == 0; });
  writer.sync();
  return out;
}

// The labelled candidates of `sets` in the frames `later`, each place (frame, strict box) once.
void labelled_in(const std::vector<std::string>& sets, const std::set<std::string>& later,
                 std::vector<cv::Mat1w>& crops, std::vector<int>& labels) {
  std::set<std::tuple<std::string, int, int, int, int>> seen;
  for (const std::string& dir : sets) {
    const SampleSet set = SampleSet::open_read(dir);
    for (std::size_t i = 0; i < set.records().size(); ++i) {
      const SampleRecord& r = set.records()[i];
      if (!r.has_crop || later.count(r.frame) == 0) continue;
      const cv::Rect& b = r.strict_box;
      if (!seen.insert({r.frame, b.x, b.y, b.width, b.height}).second) continue;
      crops.push_back(set.depth_crop(i));
      labels.push_back(r.label);
    }
  }
}

// People found at FPPF <= 0.1 by `model` among the labelled candidates.
std::size_t found_by(const BoostedModel& model, const std::vector<cv::Mat1w>& crops, const std::vector<int>& labels,
                     std::size_t frames) {
  const std::vector<double> scores = detector_scores(model, PipelineParams{}, crops);
  std::vector<double> people, others;
  for (std::size_t i = 0; i < labels.size(); ++i) (labels[i] == 1 ? people : others).push_back(scores[i]);
  return people_found_at_fppf(people, others, frames, 0.1);
}

}  // namespace

void run_holdout_check(const HoldoutInputs& in, const BoostedModel& model, AdaptState& state,
                       const TrialTraining& train) {
  const std::optional<std::vector<std::string>> names = open_frame_source(in.source)->frame_names();
  if (!names || names->size() < 2) {
    state.set("check", "none");
    say("the room's frames are not named in order (or fewer than 2): no held-out check");
    return;
  }
  const std::vector<std::string> later_names = later_half(*names);
  const std::set<std::string> later(later_names.begin(), later_names.end());
  fs::remove_all(in.dir);
  std::vector<std::string> sets;
  for (const std::string& s : in.room_sets) sets.push_back(earlier_part(s, later, true, in.dir));
  const std::string negatives =
      in.negatives.empty() ? std::string() : earlier_part(in.negatives, later, in.negatives_from_room, in.dir);
  const auto [trial, seconds] = train(sets, negatives);
  state.set("check_train_seconds", seconds);

  std::vector<std::string> scored = in.room_sets;
  if (in.negatives_from_room && !in.negatives.empty()) scored.push_back(in.negatives);
  std::vector<cv::Mat1w> crops;
  std::vector<int> labels;
  labelled_in(scored, later, crops, labels);
  HoldoutFigures f;
  f.frames = later.size();
  f.people = static_cast<std::size_t>(std::count(labels.begin(), labels.end(), 1));
  f.others = labels.size() - f.people;
  f.base_found = found_by(model, crops, labels, f.frames);
  f.trial_found = found_by(BoostedModel::load(trial), crops, labels, f.frames);
  const std::string figures = "later " + std::to_string(f.frames) + " frames, " + std::to_string(f.people) +
                              " labelled people, " + std::to_string(f.others) + " other candidates: at FPPF <= 0.1 " +
                              model_reference(model) + " finds " + std::to_string(f.base_found) +
                              ", the trial (earlier half) " + std::to_string(f.trial_found);
  state.set("check.figures", figures);
  state.set("check", f.trial_kept() ? "trial kept" : "base kept");
  say(figures + (f.trial_kept() ? ": the room's model is trained" : ": the model as given is kept"));
}

}  // namespace rdsf
