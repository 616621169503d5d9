#include "adapt/adapt_options.hpp"

#include <optional>

#include "cli/common_options.hpp"

namespace rdsf {

namespace po = cli::po;

po::options_description adapt_options(const std::string& caption, AdaptOptions& o, AdaptOptionText& text) {
  po::options_description options(caption);
  options.add_options()
      ("source", po::value(&o.source), "the room recording, with people (folder, list file, .oni, ROS 1 .bag; any resolution, with its camera model)")
      ("empty", po::value(&o.empty),
       "the room without people (mined whole; refused when the model follows a person in it over 5 frames). "
       "Default: none (the stretches of --source where the model and the tracker see nobody)")
      ("trust-empty", po::bool_switch(&o.trust_empty),
       "use --empty although the model follows a person in it over 5 frames (look at the frame the refusal "
       "names first: if nobody is there, what the model follows is the room's hardest negative)")
      ("out", po::value(&o.out), "work folder: adapt-state.tsv, sets/, logs/, report.txt (rerun to resume)")
      ("name", po::value(&o.name), "the adapted model's name: saved as MODELS/NAME/vN.yml");
  cli::add_model_option(options, o.model, "the model to adapt");
  cli::add_models_dir_option(options, o.models_dir, cli::ModelsDirUse::look_up_and_save);
  options.add_options()
      ("budget", po::value(&o.budget)->default_value(o.budget), "human answers at most (at least 1)")
      ("truth", po::value(&o.truth),
       "boxes.csv of the room: the truth is the person (headless, answers counted) and, with --eval, the report's")
      ("answers", po::value(&o.answers), "headless: the person's keys from this file (- = stdin); default: a window")
      ("eval", po::value(&o.eval), "held-out frames of the room for the before / after report (needs --truth)")
      ("per-candidate", po::bool_switch(&o.per_candidate), "ask every candidate, no propagation along tracks")
      ("retrain", po::bool_switch(&o.retrain), "train from nothing instead of continuing --model")
      ("rounds", po::value(&o.rounds)->default_value(o.rounds), ("boosting rounds (0: " + std::to_string(kContinuedRounds) + " continuing, 100 retraining)").c_str())
      ("room-weight", po::value(&o.room_weight)->default_value(o.room_weight),
       "the room's samples (answers, negatives) weigh this many times a base sample in training")
      ("base-pos", po::value(&o.base_pos)->multitoken(), "the synthetic base's positive sample set(s)")
      ("base-neg", po::value(&o.base_neg)->multitoken(), "the synthetic base's negative sample set(s)")
      ("base-frames", po::value(&o.base_frames)->default_value(o.base_frames),
       "without --base-pos/--base-neg: render a synthetic base of this many frames with people (and half as "
       "many empty) in DIR/base, once; 0: train on the room's samples alone (they can make the model worse)")
      ("base-cache", po::value(&o.base_cache),
       "without --base-pos/--base-neg: keep the rendered base in this folder instead of DIR/base (frames by their "
       "count, sets by the count and the analyser options they were cut with) and reuse what another run made "
       "there; default: DIR/base")
      ("base-cut", po::value(&text.base_cut)->default_value(text.base_cut),
       "the analyser options the base rendered here is cut with: defaults (the detector's, as the shipped model's "
       "training), stated (given and stated by --model) or steps (those and the switches the trials took); the "
       "room's own samples have the steps' options either way");
  options.add_options()
      ("try-switches", po::value(&o.try_switches)->default_value(o.try_switches, o.try_switches ? "on" : "off"),
       "on or off: try each candidate switch not given nor turned on by the model (--local-front 70, "
       "--border-height 25, --narrow-fitted-width 20, --hole-gap 20) in the room first: the person is asked about "
       "the candidates only it adds, likeliest first; one confirmed person turns it on for every step and the "
       "adapted model")
      ("holdout-check", po::value(&text.holdout_check)->default_value("auto"),
       ("auto, on or off: before training, train a trial model on the earlier half of the room's frames and "
       "compare it with --model (stating the switches taken) on the labelled candidates of the later half; when "
       "the trial finds fewer people at 0.1 false positives per frame, the room's model is --model as given (no "
       "round added). auto: on when the base sets hold 1 to " + std::to_string(kHoldoutCheckMaxBaseSamples) +
       " samples (the small base rendered here: about 1 s more), off for larger ones (a second training of their "
       "size) and without a base").c_str())
      ("check-as-given", po::value(&o.check_as_given)->default_value(o.check_as_given, o.check_as_given ? "on" : "off"),
       "on or off: with switches taken, the held-out check also judges --model without them on its own candidates "
       "of the later half; when it finds more people than both the trial and --model stating the switches, the "
       "room's model is --model as given, the switches dropped")
      ("trial-budget", po::value(&o.trial_budget)->default_value(o.trial_budget),
       "--try-switches: answers at most per switch (of --budget; the trials take at most half of it)")
      ("switch-rule", po::value(&text.switch_rule)->default_value(text.switch_rule),
       "--try-switches: one (each switch tried alone; one confirmed person takes it) or majority (each tried on "
       "the switches taken before it; taken when the answers confirm more people than they reject)");
  cli::add_per_place_option(options, o.per_place);
  cli::add_propagate_model_option(options, o.propagate_model);
  cli::add_threads_option(options, o.threads, "threads of each step");
  options.add(cli::analyser_options(o.analyser, /*feature_spec=*/false));  // the model's features
  options.add_options()
      ("chart", po::value(&text.chart), "instead: draw scripts/adaptation-benchmark.sh's results.tsv as --chart-png")
      ("chart-png", po::value(&text.chart_png), "with --chart: the picture to write");
  return options;
}

void check_options(const AdaptOptionText& text, AdaptOptions& o) {
  if (!text.chart.empty()) {
    if (text.chart_png.empty()) throw cli::UsageError("--chart needs --chart-png");
    return;
  }
  if (o.source.empty() || o.out.empty() || o.name.empty()) {
    throw cli::UsageError("give --source ROOM, --out DIR and --name NAME (see rdsf-adapt --help)");
  }
  if (o.budget < 1) throw cli::UsageError("--budget " + std::to_string(o.budget) + ": adapting needs answers, give 1 or more");
  if (!o.eval.empty() && o.truth.empty()) throw cli::UsageError("--eval needs --truth");
  if (o.trust_empty && o.empty.empty()) throw cli::UsageError("--trust-empty needs --empty");
  if (!o.truth.empty() && !o.answers.empty()) throw cli::UsageError("give --truth (the truth answers) or --answers, not both");
  if (o.rounds < 0) throw cli::UsageError("--rounds must be 0 (the default) or more");
  if (o.room_weight < 1) throw cli::UsageError("--room-weight must be at least 1");
  if (o.base_frames < 0) throw cli::UsageError("--base-frames must be 0 (no base) or more");
  if (!o.base_cache.empty() && (!o.base_pos.empty() || !o.base_neg.empty() || o.base_frames == 0)) {
    throw cli::UsageError("--base-cache keeps the base rendered here: not with --base-pos, --base-neg or --base-frames 0");
  }
  if (text.holdout_check == "on" || text.holdout_check == "off") o.holdout_check = text.holdout_check == "on";
  else if (text.holdout_check != "auto") throw cli::UsageError("--holdout-check takes auto, on or off, not '" + text.holdout_check + "'");
  using BaseCut = AdaptOptions::BaseCut;
  std::optional<BaseCut> cut;
  for (const BaseCut c : {BaseCut::steps, BaseCut::stated, BaseCut::defaults}) {
    if (text.base_cut == AdaptOptions::base_cut_name(c)) cut = c;
  }
  if (!cut) throw cli::UsageError("--base-cut takes steps, stated or defaults, not '" + text.base_cut + "'");
  o.base_cut = *cut;
  if (text.switch_rule == "one" || text.switch_rule == "majority") o.switch_majority = text.switch_rule == "majority";
  else throw cli::UsageError("--switch-rule takes one or majority, not '" + text.switch_rule + "'");
  if (o.trial_budget < 1) throw cli::UsageError("--trial-budget must be at least 1 (--try-switches off tries none)");
}

}  // namespace rdsf
