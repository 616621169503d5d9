// rdsf-label: a person confirms the frame analyser's candidates one by one (y / n / skip / undo / quit);
// every answer is stored before the next candidate appears, and a rerun resumes where it stopped.

#include "cli/cli.hpp"
#include "cli/common_options.hpp"
#include "rdsf/core/error.hpp"
#include "label_run.hpp"

int main(int argc, char** argv) {
  return rdsf::cli::run("rdsf-label", [&] {
    namespace po = rdsf::cli::po;
    rdsf::LabelOptions o;
    bool no_model_answers = false;
    std::string ask = "order";
    int explore = 5;
    po::options_description options("rdsf-label");
    options.add_options()
        ("source", po::value(&o.session.sources)->required()->composing(),
         "frames to label (repeat for several): folder, list file, PNG, .oni, 'openni' or device URI")
        ("out", po::value(&o.out_set)->required(), "sample set to append to (created when missing)");
    rdsf::cli::add_model_option(options, o.model, "show each candidate's score H(x) with this model");
    rdsf::cli::add_models_dir_option(options, o.models_dir);
    options.add_options()
        ("accept", po::value(&o.session.accept_probability)
                      ->default_value(o.session.accept_probability, rdsf::cli::shortest_text(o.session.accept_probability)),
         "with --model: candidates with P(person) >= this are answered y by the model, never shown")
        ("reject", po::value(&o.session.reject_probability)->default_value(o.session.reject_probability),
         "with --model: candidates with P(person) <= this are answered n by the model, never shown")
        ("no-model-answers", po::bool_switch(&no_model_answers), "with --model: ask every candidate (only show the score)")
        ("ask", po::value(&ask)->default_value(ask),
         "order: frame after frame; uncertain (needs --model): the whole session closest to P = 0.5 first")
        ("loop", po::bool_switch(&o.loop),
         "active learning: ask --batch answers (most uncertain first), retrain in-process, re-score, ask the next "
         "batch; models saved as --loop-model NAME/vN; implies --ask uncertain and --keep-rejected")
        ("batch", po::value(&o.batch)->default_value(o.batch), "--loop: human answers per batch")
        ("loop-model", po::value(&o.loop_model)->default_value(o.loop_model), "--loop: name of the models trained")
        ("loop-answer-after", po::value(&o.loop_answer_after)->default_value(o.loop_answer_after),
         "--loop: at the loop's end its last model answers the candidates it is sure about (--accept/--reject), "
         "if the person gave at least this many y and as many n")
        ("explore", po::value(&explore)->default_value(explore),
         "--loop: every Nth candidate asked is a random one, not the most uncertain (finds what the model "
         "wrongly is sure of; 0 = off)")
        ("budget", po::value(&o.budget)->default_value(o.budget), "stop after this many human answers (0: no limit)");
    rdsf::cli::add_threads_option(options, o.session.threads,
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
         "one answer per track (needs --ask uncertain): a y or n is given to the candidates on the same person's "
         "track in the frames before and after while the track is sure (docs/adapting-to-your-room.md); the window "
         "shows the track as a strip of crops; u undoes the whole track");
    rdsf::cli::add_per_place_option(options, o.session.propagation.per_place);
    rdsf::cli::CameraOptions camera(options, o.session.camera);
    options.add(rdsf::cli::analyser_options(o.session.analyser));
    po::variables_map values;
    const rdsf::cli::ProgramInfo info{
        "rdsf-label", "--source SRC... --out SET [--model M [--accept P --reject P] [--ask uncertain]] [--loop [--batch N]]\n"
        "    [--budget N] [--truth boxes.csv] [--answers FILE|-] [--keep-rejected]",
        "Shows each candidate of each frame; keys: y person, n not a person, s/space skip, u/backspace undo\n"
        "(also across frames), q/Esc save and quit. Every answer is stored before the next candidate appears;\n"
        "run again on the same sources and set to resume. With --model, candidates the model is sure about are\n"
        "answered by it (journalled 'by model') and never shown. --answers takes the same keys as whitespace-separated\n"
        "tokens (y n s u q, space, backspace, esc; 'yyn' is three keys)."};
    if (!rdsf::cli::parse(argc, argv, info, options, values)) return 0;
    camera.apply(values);
    o.session.model_answers = !no_model_answers;
    try {
      o.session.ask = rdsf::parse_ask_order(ask);
    } catch (const rdsf::Error& e) {
      throw rdsf::cli::UsageError(std::string("--ask: ") + e.what());
    }
    if (o.loop) {  // --loop asks the uncertain candidates first and keeps the rejected ones
      o.session.ask = rdsf::AskOrder::uncertain;
      o.session.keep_rejected = true;
      o.session.explore_every = explore;
    }
    rdsf::check_options(o);
    return rdsf::run_label(o);
  });
}
