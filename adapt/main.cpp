// rdsf-adapt: a detector for a lab's own room from the fewest answers: room negatives, the person's answers
// (one per track), training on the room's samples with the synthetic base, a report. Resumable.
#include "adapt/adapt_chart.hpp"
#include "adapt/adapt_run.hpp"
#include "cli/cli.hpp"
#include "cli/common_options.hpp"

const rdsf::cli::ProgramInfo kProgram{
    "rdsf-adapt", "--source ROOM [--empty EMPTY] --out DIR --name NAME [--budget N] [--truth boxes.csv [--eval HELD_OUT]]",
    "Adapts a model to a room in resumable steps, each one of the workbench's programs: the candidate switches\n"
    "tried (rdsf-label --only-added-by: is what each adds a person?), a synthetic base when none is given\n"
    "(rdsf-synth, rdsf-label, rdsf-mine), negatives (rdsf-mine), the person's answers, one per\n"
    "track (rdsf-label --per-track), training (rdsf-train --init), report (rdsf-detect). Killed, it resumes at\n"
    "the step it was in; nothing answered is lost. Candidate and segmentation options given here are used by\n"
    "every step, and the adapted model states them, so rdsf-detect and the ROS node run it with them.\n"
    "docs/adapting-to-your-room.md"};

int main(int argc, char** argv) {
  return rdsf::cli::run(kProgram.name, [&] {
    namespace po = rdsf::cli::po;
    rdsf::AdaptOptions o;
    std::string chart, chart_png, holdout_check;
    po::options_description options(kProgram.name);
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
    rdsf::cli::add_model_option(options, o.model, "the model to adapt");
    rdsf::cli::add_models_dir_option(options, o.models_dir, rdsf::cli::ModelsDirUse::look_up_and_save);
    options.add_options()
        ("budget", po::value(&o.budget)->default_value(o.budget), "human answers at most (at least 1)")
        ("truth", po::value(&o.truth),
         "boxes.csv of the room: the truth is the person (headless, answers counted) and, with --eval, the report's")
        ("answers", po::value(&o.answers), "headless: the person's keys from this file (- = stdin); default: a window")
        ("eval", po::value(&o.eval), "held-out frames of the room for the before / after report (needs --truth)")
        ("per-candidate", po::bool_switch(&o.per_candidate), "ask every candidate, no propagation along tracks")
        ("retrain", po::bool_switch(&o.retrain), "train from nothing instead of continuing --model")
        ("rounds", po::value(&o.rounds)->default_value(o.rounds), ("boosting rounds (0: " + std::to_string(rdsf::kContinuedRounds) + " continuing, 100 retraining)").c_str())
        ("room-weight", po::value(&o.room_weight)->default_value(o.room_weight),
         "the room's samples (answers, negatives) weigh this many times a base sample in training")
        ("base-pos", po::value(&o.base_pos)->multitoken(), "the synthetic base's positive sample set(s)")
        ("base-neg", po::value(&o.base_neg)->multitoken(), "the synthetic base's negative sample set(s)")
        ("base-frames", po::value(&o.base_frames)->default_value(o.base_frames),
         "without --base-pos/--base-neg: render a synthetic base of this many frames with people (and half as "
         "many empty) in DIR/base, once; 0: train on the room's samples alone (they can make the model worse)");
    options.add_options()
        ("try-switches", po::value(&o.try_switches)->default_value(o.try_switches, o.try_switches ? "on" : "off"),
         "on or off: try each candidate switch not given nor turned on by the model (--local-front 70, "
         "--border-height 25, --narrow-fitted-width 20, --hole-gap 20) in the room first: the person is asked about "
         "the candidates only it adds, likeliest first; one confirmed person turns it on for every step and the "
         "adapted model")
        ("holdout-check", po::value(&holdout_check)->default_value("auto"),
         ("auto, on or off: before training, train a trial model on the earlier half of the room's frames and "
         "compare it with --model (stating the switches taken) on the labelled candidates of the later half; when "
         "the trial finds fewer people at 0.1 false positives per frame, the room's model is --model as given (no "
         "round added). auto: on when the base sets hold 1 to " + std::to_string(rdsf::kHoldoutCheckMaxBaseSamples) +
         " samples (the small base rendered here: about 1 s more), off for larger ones (a second training of their "
         "size) and without a base").c_str())
        ("trial-budget", po::value(&o.trial_budget)->default_value(o.trial_budget),
         "--try-switches: answers at most per switch (of --budget; the trials take at most half of it)");
    rdsf::cli::add_per_place_option(options, o.per_place);
    rdsf::cli::add_propagate_model_option(options, o.propagate_model);
    rdsf::cli::add_threads_option(options, o.threads, "threads of each step");
    options.add(rdsf::cli::analyser_options(o.analyser, /*feature_spec=*/false));  // the model's features
    options.add_options()
        ("chart", po::value(&chart), "instead: draw scripts/adaptation-benchmark.sh's results.tsv as --chart-png")
        ("chart-png", po::value(&chart_png), "with --chart: the picture to write");
    po::variables_map values;
    if (!rdsf::cli::parse(argc, argv, kProgram, options, values)) return 0;
    o.given = rdsf::cli::given_analyser_options(values);
    if (!chart.empty()) {
      if (chart_png.empty()) throw rdsf::cli::UsageError("--chart needs --chart-png");
      rdsf::write_adaptation_chart(chart, chart_png);
      return 0;
    }
    if (o.source.empty() || o.out.empty() || o.name.empty()) {
      throw rdsf::cli::UsageError("give --source ROOM, --out DIR and --name NAME (see rdsf-adapt --help)");
    }
    if (o.budget < 1) throw rdsf::cli::UsageError("--budget " + std::to_string(o.budget) + ": adapting needs answers, give 1 or more");
    if (!o.eval.empty() && o.truth.empty()) throw rdsf::cli::UsageError("--eval needs --truth");
    if (o.trust_empty && o.empty.empty()) throw rdsf::cli::UsageError("--trust-empty needs --empty");
    if (!o.truth.empty() && !o.answers.empty()) throw rdsf::cli::UsageError("give --truth (the truth answers) or --answers, not both");
    if (o.rounds < 0) throw rdsf::cli::UsageError("--rounds must be 0 (the default) or more");
    if (o.room_weight < 1) throw rdsf::cli::UsageError("--room-weight must be at least 1");
    if (o.base_frames < 0) throw rdsf::cli::UsageError("--base-frames must be 0 (no base) or more");
    if (holdout_check == "on" || holdout_check == "off") o.holdout_check = holdout_check == "on";
    else if (holdout_check != "auto") throw rdsf::cli::UsageError("--holdout-check takes auto, on or off, not '" + holdout_check + "'");
    if (o.trial_budget < 1) throw rdsf::cli::UsageError("--trial-budget must be at least 1 (--try-switches off tries none)");
    return rdsf::run_adapt(o);
  });
}
