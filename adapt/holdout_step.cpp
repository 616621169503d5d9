#include "adapt/holdout_step.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <tuple>

#include "rdsf/candidates/candidate_finder.hpp"
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
struct LabelledPlace {
  std::string frame;
  cv::Rect strict_box;
  int label = 0;
};
struct LaterScores {
  std::vector<double> base_people, base_others, trial_people, trial_others;
  std::vector<LabelledPlace> places;  ///< what was scored, in order
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
      out.places.push_back({r.frame, box, r.label});
      if (crops.size() == kBatch) flush();
    }
  }
  flush();
  return out;
}

// The model as given with the analyser `as_given` (no switches) on the later half's frames of `source` (`names`:
// its frame names in order; the earlier half is read past, not decoded): its own candidates scored as the
// detector scores them, each labelled place taking the highest score among the candidates of its frame whose
// strict box overlaps it at IoU >= 0.5; people_found_at_fppf of those (a person no candidate overlaps is missed;
// candidates that overlap no labelled place count for neither).
std::size_t as_given_found(const std::string& source, const std::vector<std::string>& names,
                           const std::set<std::string>& later, const AnalyserParams& as_given,
                           const BoostedModel& model, const std::vector<LabelledPlace>& places) {
  std::map<std::string, std::vector<std::pair<cv::Rect, double>>> scored;  // frame -> (strict box, score)
  const FrameAnalyser analyser(as_given);
  const std::unique_ptr<FrameSource> frames = open_frame_source(source);
  FrameDecode decode;
  for (std::size_t at = 0; at < names.size() && frames->next_deferred(decode); ++at) {
    if (later.count(names[at]) == 0) continue;
    const DepthFrame frame = decode();
    const FrameAnalysis analysis = analyser.analyse(frame, /*with_features=*/false, CropColour::later);
    std::vector<cv::Mat1w> crops;
    for (const Candidate& c : analysis.candidates) crops.push_back(c.depth_crop);
    const std::vector<double> scores = detector_scores(model, PipelineParams{}, crops);
    auto& boxes = scored[frame.name];
    for (std::size_t i = 0; i < scores.size(); ++i) boxes.emplace_back(analysis.candidates[i].strict_box, scores[i]);
  }
  std::vector<double> people, others;
  for (const LabelledPlace& p : places) {
    std::optional<double> best;
    const auto in_frame = scored.find(p.frame);
    if (in_frame != scored.end()) {
      for (const auto& [box, score] : in_frame->second) {
        if (iou(box, p.strict_box) >= 0.5 && (!best || score > *best)) best = score;
      }
    }
    if (p.label == 1) people.push_back(best.value_or(-std::numeric_limits<double>::infinity()));
    else if (best) others.push_back(*best);
  }
  return people_found_at_fppf(people, others, later.size(), 0.1);
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
  if (in.as_given) f.as_given_found = as_given_found(in.source, *names, later, *in.as_given, model, scores.places);
  const std::string figures =
      "later " + std::to_string(f.frames) + " frames, " + std::to_string(f.people) + " labelled people, " +
      std::to_string(f.others) + " other candidates: at FPPF <= 0.1 " + model_reference(model) +
      (f.as_given_found ? " finds " + std::to_string(*f.as_given_found) + " without the switches, " +
                              std::to_string(f.base_found) + " with them"
                        : " finds " + std::to_string(f.base_found)) +
      ", the trial (earlier half) " + std::to_string(f.trial_found);
  state.set("check.figures", figures);
  state.set("check", f.as_given_kept() ? "as given kept" : f.trial_kept() ? "trial kept" : "base kept");
  say(figures + (f.as_given_kept() ? ": the model as given is kept, without the switches"
                 : f.trial_kept()  ? ": the room's model is trained"
                                   : ": the model as given is kept"));
}

}  // namespace rdsf
