// rdsf-adapt: a detector for a lab's own room from the fewest answers: room negatives, the person's answers
// (one per track), training on the room's samples with the synthetic base, a report. Resumable.
#include "adapt/adapt_chart.hpp"
#include "adapt/adapt_options.hpp"
#include "adapt/adapt_run.hpp"
#include "cli/cli.hpp"

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
    rdsf::AdaptOptions o;
    rdsf::AdaptOptionText text;
    rdsf::cli::po::options_description options = rdsf::adapt_options(kProgram.name, o, text);
    rdsf::cli::po::variables_map values;
    if (!rdsf::cli::parse(argc, argv, kProgram, options, values)) return 0;
    o.given = rdsf::cli::given_analyser_options(values);
    rdsf::check_options(text, o);
    if (!text.chart.empty()) {
      rdsf::write_adaptation_chart(text.chart, text.chart_png);
      return 0;
    }
    return rdsf::run_adapt(o);
  });
}
