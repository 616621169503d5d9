#include "labeler/label_options.hpp"

#include <string>

#include "cli/common_options.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {

cli::po::options_description label_options(LabelOptions& o, LabelOptionText& text) {
  namespace po = cli::po;
  po::options_description options("rdsf-label");
  options.add_options()
      ("source", po::value(&o.session.sources)->required()->composing(),
       "frames to label (repeat for several): folder, list file, PNG, .oni, 'openni' or device URI")
      ("out", po::value(&o.out_set)->required(), "sample set to append to (created when missing)");
  cli::add_model_option(options, o.model, "show each candidate's score H(x) with this model");
  cli::add_models_dir_option(options, o.models_dir);
  options.add_options()
      ("accept", po::value(&o.session.accept_probability)
                    ->default_value(o.session.accept_probability, cli::shortest_text(o.session.accept_probability)),
       "with --model: candidates with P(person) >= this are answered y by the model, never shown")
      ("reject", po::value(&o.session.reject_probability)->default_value(o.session.reject_probability),
       "with --model: candidates with P(person) <= this are answered n by the model, never shown")
      ("no-model-answers", po::bool_switch(&text.no_model_answers), "with --model: ask every candidate (only show the score)")
      ("ask", po::value(&text.ask)->default_value(text.ask),
       "order: frame after frame; uncertain (needs --model): the whole session closest to P = 0.5 first; likely "
       "(needs --model): the whole session, the highest P(person) first")
      ("only-added-by", po::value(&o.only_added_by),
       "an analyser option (e.g. local-front): only the candidates it adds are asked and stored, not those the "
       "same options with it at its default make too (IoU >= 0.5); rdsf-adapt's trials of the candidate switches")
      ("loop", po::bool_switch(&o.loop),
       "active learning: ask --batch answers (most uncertain first), retrain in-process, re-score, ask the next "
       "batch; models saved as --loop-model NAME/vN; implies --ask uncertain and --keep-rejected")
      ("batch", po::value(&o.batch)->default_value(o.batch), "--loop: human answers per batch")
      ("loop-model", po::value(&o.loop_model)->default_value(o.loop_model), "--loop: name of the models trained")
      ("loop-answer-after", po::value(&o.loop_answer_after)->default_value(o.loop_answer_after),
       "--loop: at the loop's end its last model answers the candidates it is sure about (--accept/--reject), "
       "if the person gave at least this many y and as many n")
      ("explore", po::value(&text.explore)->default_value(text.explore),
       "--loop: every Nth candidate asked is a random one, not the most uncertain (finds what the model "
       "wrongly is sure of; 0 = off)")
      ("budget", po::value(&o.budget)->default_value(o.budget), "stop after this many human answers (0: no limit)");
  cli::add_threads_option(options, o.session.threads,
                                "--ask uncertain / --loop: threads that analyse and score the session's frames "
                                "before the first question", "the same session for every count");
  options.add_options()
      ("order-by-score", po::bool_switch(&o.session.order_by_score), "present a frame's candidates best score first")
      ("truth", po::value(&o.truth_csv),
       "assisted mode: boxes.csv; IoU >= 0.5 answers y, < 0.3 answers n, only the band between is asked")
      ("truth-oracle", po::bool_switch(&o.session.truth_is_oracle),
       "with --truth, for benchmarks: the truth is the person, answering the candidates asked (y, n, or s in the "
       "band between) instead of the sure ones silently; no --answers needed")
      ("min-visible", po::value(&o.min_visible)->default_value(o.min_visible),
       "assisted mode: people with visible_fraction below this are don't-care (as rdsf-detect's evaluation): "
       "their candidates are asked, not answered")
      ("answers", po::value(&o.answers), "headless: read keys from this file (- = stdin) instead of a window")
      ("keep-rejected", po::bool_switch(&o.session.keep_rejected), "store 'n' answers as negatives (label 0)")
      ("per-track", po::bool_switch(&o.session.per_track),
       "one answer per track (needs --ask uncertain or likely): a y or n is given to the candidates on the same person's "
       "track in the frames before and after while the track is sure (docs/adapting-to-your-room.md); the window "
       "shows the track as a strip of crops; u undoes the whole track");
  cli::add_per_place_option(options, o.session.propagation.per_place);
  cli::add_propagate_model_option(options, o.session.propagation.from_model);
  options.add_options()
      ("model-track-max-no", po::value(&o.session.propagation.model_max_no_probability)
                                 ->default_value(o.session.propagation.model_max_no_probability,
                                                 cli::shortest_text(o.session.propagation.model_max_no_probability)),
       "--propagate-model-answers on: the track of a model's n enters only candidates with P(person) <= this")
      ("model-track-within-image",
       po::value(&o.session.propagation.model_within_image)
           ->default_value(o.session.propagation.model_within_image,
                           o.session.propagation.model_within_image ? "on" : "off"),
       "--propagate-model-answers on (on or off): the model's tracks neither start at nor enter a candidate whose "
       "window reaches beyond the image (a crop cut by the image's edge, where the model is least sure)");
  return options;
}

void apply_option_text(const LabelOptionText& text, LabelOptions& o) {
  o.session.model_answers = !text.no_model_answers;
  try {
    o.session.ask = parse_ask_order(text.ask);
  } catch (const Error& e) {
    throw cli::UsageError(std::string("--ask: ") + e.what());
  }
  if (o.loop) {  // --loop asks the uncertain candidates first and keeps the rejected ones
    o.session.ask = AskOrder::uncertain;
    o.session.keep_rejected = true;
    o.session.explore_every = text.explore;
  }
}

}  // namespace rdsf
