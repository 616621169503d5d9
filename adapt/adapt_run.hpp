#pragma once
// rdsf-adapt's work: a room's own detector from the fewest answers, in steps that each run one of the
// workbench's programs (docs/adapting-to-your-room.md), resumable after a kill (adapt_state.hpp):
//   0. switches   the candidate switches (pipeline/candidate_switches.hpp) not given nor turned on by the model
//                 (people/v4 turns on local-front), each tried in the room: the person is asked, likeliest first,
//                 about the candidates only it adds (rdsf-label --ask likely --only-added-by, one answer per
//                 track, --trial-budget answers each, at most half the --budget in all); a switch with a person
//                 confirmed among them is on for every later step and the adapted model
//      base       without --base-pos/--base-neg: a small synthetic base rendered and labelled here (rdsf-synth,
//                 rdsf-label from its truth, rdsf-mine; in --base-cache when given, shared by the runs given it),
//                 so that the room's few samples never train alone
//   1. negatives  the room's people-free frames mined (rdsf-mine): the --empty recording, the shipped
//                 model's false positives (hard negatives) first; without one, the stretches of the room
//                 recording where the model and the tracker see nobody (pipeline/room_presence.hpp)
//   2. answers    the model answers what it is sure of, the person the rest, most uncertain first, one
//                 answer per track, within --budget (rdsf-label --ask uncertain --per-track)
//      check      with --holdout-check on: a trial model trained on the earlier half of the room's frames against
//                 the model as given on the later half's labelled candidates (pipeline/holdout_check.hpp)
//   3. train      the room's samples with the base sets, continuing the model (--init) or from nothing
//                 (rdsf-train), saved as a new version of --name with the room, answers and base recorded,
//                 stating the analyser options the steps ran with (--detection-options)
//   4. report     before / after on held-out frames with --truth and --eval (rdsf-detect), else the
//                 answers spent and the new model's validation
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "rdsf/analysis/frame_analyser.hpp"
#include "rdsf/labeling/track_propagation.hpp"
#include "rdsf/pipeline/stated_options.hpp"

namespace rdsf {

/// Rounds a room's model continues the given one by default (--rounds 0): 3 since 2026-12-07 (10 before). More
/// rounds fit the room's few dozen samples more closely and lose people the shipped model found: two rules written
/// first, each judged on a rendering made for it, took 5 over 10 and then 3 over 5. Over five renderings of 16
/// rooms 3 rounds found 1,586 people, 5 rounds 1,583 (on four of them 10 rounds 1,395, 3 rounds 1,404), and lost
/// 5 of the people the shipped model found against 13 (seed 141 alone found 9 fewer with 3 than with 5); 30 made
/// the lab room worse; 1 and 2 rounds found fewer people than 3 and lost more, and the switches alone (no round)
/// 34 fewer over the five (docs/adapting-to-your-room.md, "Fewer rounds" and "Fewer still, none, and two fresh
/// renderings").
inline constexpr int kContinuedRounds = 3;

/// --holdout-check auto is on for a base of at most this many samples: it was judged with the small base (6,155
/// samples, the benchmark's, which rdsf-adapt's own is since 2026-12-08), where the trial trains in about a second
/// (2 of 4 lost people kept over 47 rooms).
/// It costs one more training of the base's size, 28-42 s at the default model's (180,131 samples), where it
/// changed nothing on two renderings and would take the time from the last answer to the room's model past a
/// minute; no base (--base-frames 0) was not measured: off.
inline constexpr std::size_t kHoldoutCheckMaxBaseSamples = 20000;

struct AdaptOptions {
  std::string source;   ///< the room recording (frames with people)
  std::string empty;    ///< the room without people (optional)
  bool trust_empty = false;  ///< --empty is used although the model follows a person in it (the user has looked)
  std::string out;      ///< work folder: state, sample sets, logs, report
  std::string name;     ///< the adapted model's name (a new version of it is written)
  std::string model = "people";  ///< the model to adapt (file, NAME or NAME/vN)
  std::string models_dir = "models";
  long budget = 50;     ///< human answers at most
  std::string truth;    ///< boxes.csv: the truth is the person (headless) and the report's truth
  std::string answers;  ///< headless keys (rdsf-label --answers); neither: the window
  std::string eval;     ///< held-out frames of the room for the report (with truth)
  bool per_candidate = false;  ///< ask every candidate (no propagation; the benchmark's comparison)
  bool per_place = PropagationParams{}.per_place;  ///< with per track: one answer per place for n answers
  bool propagate_model = PropagationParams{}.from_model;  ///< with per track: the model's answers along tracks too
  bool retrain = false;        ///< train from nothing instead of continuing the model
  int rounds = 0;              ///< 0: kContinuedRounds continuing, 100 retraining
  /// The room's sample sets (its answers and its negatives) are given to rdsf-train this many times: each of
  /// their samples starts boosting with this many times its weight against the base's (1: as many as a base
  /// sample).
  int room_weight = 1;
  std::vector<std::string> base_pos, base_neg;  ///< the synthetic base sample sets
  /// Without base sets: frames with people of the base rendered here (and half as many empty); 0: no base
  /// (the room's samples alone).
  int base_frames = 600;
  /// Without base sets: the base is kept in this folder instead of the work folder, its frames named by their
  /// count and its sets by the count and the analyser options they were cut with, and every run given the same
  /// folder reuses what is there (the benchmark's rooms share one). Empty: in the work folder (OUT/base).
  std::string base_cache;
  /// The analyser options the base rendered here is cut with (its people labelled, its empty frames mined). The
  /// detector's defaults since 2026-12-08 (rule R36, judged on fresh renderings: 21 more close people of 1,121 and
  /// 9 more ordinary ones of 910, fewer of the shipped model's lost, than with the steps' options): the shipped
  /// model's own training was cut so, while the room's samples have the options the adapted model runs with.
  enum class BaseCut {
    steps,     ///< those every step runs with: given, stated by the model, the switches the trials took
    stated,    ///< given and stated by the model, without the switches
    defaults,  ///< the detector's defaults
  };
  BaseCut base_cut = BaseCut::defaults;
  /// The word of --base-cut and of the state file for each BaseCut.
  static const char* base_cut_name(BaseCut cut) {
    return cut == BaseCut::steps ? "steps" : cut == BaseCut::stated ? "stated" : "defaults";
  }
  /// Try the candidate switches in the room (the "switches" step); each trial spends at most trial_budget of
  /// the budget's answers, all of them at most half the budget.
  bool try_switches = true;
  int trial_budget = 3;
  /// How a trial decides (--switch-rule). false ("one"): each switch is tried alone with the model's options and
  /// one person the person confirms among the candidates only it adds takes it. true ("majority"): each is
  /// tried with the switches taken before it on (what it adds to them is asked), and it is taken when the
  /// person's answers there confirm more people than they reject (y > n; skips count for neither).
  bool switch_majority = false;
  /// Before training (the "check" step): a trial model of the earlier half of the room's frames against the
  /// model as given on the labelled candidates of the later half; the trial finding fewer people keeps the model
  /// as given (pipeline/holdout_check.hpp). Unset ("auto"): on when the base sets hold 1 to
  /// kHoldoutCheckMaxBaseSamples samples.
  std::optional<bool> holdout_check;
  /// With switches taken, the held-out check also judges the model as given without them, which wins when it
  /// finds more than both others: the switches are dropped (pipeline/holdout_check.hpp).
  bool check_as_given = false;
  int threads = 0;
  /// The frame analyser's options (segmentation, candidates) and which were given: every step runs with the
  /// given ones, the model's stated ones for the rest (pipeline/stated_options.hpp), and the adapted model
  /// states them all when any was given or the model states any (else what its sample sets record).
  AnalyserParams analyser;
  GivenOptions given;
};

int run_adapt(const AdaptOptions& options);

}  // namespace rdsf
