#include "adapt/holdout_step.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
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

// `input`'s samples outside the frames `later`, copied into a set in `dir`: its path.
std::string earlier_part(const std::string& input, const std::set<std::string>& later, const std::string& dir) {
  const SampleSet set = SampleSet::open_read(input);
  const std::string out = (fs::path(dir) / ("earlier-" + fs::path(input).filename().string())).string();
  SampleSetWriter writer = SampleSetWriter::open_or_create(out, set.feature_spec(), set.manifest().camera,
                                                           "rdsf-adapt --holdout-check", set.manifest().crops,
                                                           set.manifest().analyser_options);
  merge_sample_sets({input}, writer, [&](const SampleRecord& r) { return later.count(r.frame) == 0; });
  writer.sync();
  return out;
}

// Scores of the labelled candidates of `sets` in the frames `later`, each place (frame, strict box) once, by the
// model as given and by the trial, split by label; crops read and scored in batches (a long recording's later
// half may hold tens of thousands).
struct LaterScores {
  std::vector<double> base_people, base_others, trial_people, trial_others;
};
LaterScores score_later(const std::vector<std::string>& sets, const std::set<std::string>& later,
                        const BoostedModel& base, const BoostedModel& trial) {
  constexpr std::size_t kBatch = 512;
  const PipelineParams params;  // the detector's defaults: mirror scoring
  LaterScores out;
  std::vector<cv::Mat1w> crops;
  std::vector<int> labels;
  const auto flush = [&] {
    const std::vector<double> b = detector_scores(base, params, crops), t = detector_scores(trial, params, crops);
    for (std::size_t i = 0; i < labels.size(); ++i) {
      (labels[i] == 1 ? out.base_people : out.base_others).push_back(b[i]);
      (labels[i] == 1 ? out.trial_people : out.trial_others).push_back(t[i]);
    }
    crops.clear();
    labels.clear();
  };
  std::set<std::tuple<std::string, int, int, int, int>> seen;
  for (const std::string& dir : sets) {
    const SampleSet set = SampleSet::open_read(dir);
    for (std::size_t i = 0; i < set.records().size(); ++i) {
      const SampleRecord& r = set.records()[i];
      if (!r.has_crop || later.count(r.frame) == 0) continue;
      const cv::Rect& box = r.strict_box;
      if (!seen.insert({r.frame, box.x, box.y, box.width, box.height}).second) continue;
      crops.push_back(set.depth_crop(i));
      labels.push_back(r.label);
      if (crops.size() == kBatch) flush();
    }
  }
  flush();
  return out;
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
  for (const std::string& s : in.room_sets) sets.push_back(earlier_part(s, later, in.dir));
  // Negatives of another recording (--empty) are all the trial's: their set as it is.
  const std::string negatives = in.negatives.empty() || !in.negatives_from_room
                                    ? in.negatives
                                    : earlier_part(in.negatives, later, in.dir);
  const auto [trial, seconds] = train(sets, negatives);
  state.set("check_train_seconds", seconds);

  std::vector<std::string> scored = in.room_sets;
  if (in.negatives_from_room && !in.negatives.empty()) scored.push_back(in.negatives);
  const LaterScores scores = score_later(scored, later, model, BoostedModel::load(trial));
  HoldoutFigures f;
  f.frames = later.size();
  f.people = scores.base_people.size();
  f.others = scores.base_others.size();
  f.base_found = people_found_at_fppf(scores.base_people, scores.base_others, f.frames, 0.1);
  f.trial_found = people_found_at_fppf(scores.trial_people, scores.trial_others, f.frames, 0.1);
  const std::string figures = "later " + std::to_string(f.frames) + " frames, " + std::to_string(f.people) +
                              " labelled people, " + std::to_string(f.others) + " other candidates: at FPPF <= 0.1 " +
                              model_reference(model) + " finds " + std::to_string(f.base_found) +
                              ", the trial (earlier half) " + std::to_string(f.trial_found);
  state.set("check.figures", figures);
  state.set("check", f.trial_kept() ? "trial kept" : "base kept");
  say(figures + (f.trial_kept() ? ": the room's model is trained" : ": the model as given is kept"));
}

}  // namespace rdsf
