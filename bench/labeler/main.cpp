// rdsf-labeler-bench: how few answers the labeler needs (active learning), how often its model answers are
// wrong, how fast the review finds planted label errors; ground truth answers (labeler_bench.hpp).
#include "cli/cli.hpp"
#include "cli/common_options.hpp"
#include "labeler_bench.hpp"

const rdsf::cli::ProgramInfo kProgram{"rdsf-labeler-bench", "--train DIR... --test DIR... [--batch N]",
                                      "The labeler's benchmark with ground truth as the oracle; prints Markdown."};

int main(int argc, char** argv) {
  return rdsf::cli::run(kProgram.name, [&] {
    namespace po = rdsf::cli::po;
    rdsf::bench::LabelerBenchOptions o;
    po::options_description options(kProgram.name);
    options.add_options()
        ("train", po::value(&o.train)->required()->composing(), "labelled recordings of the pool (boxes.csv)")
        ("test", po::value(&o.test)->required()->composing(), "held-out labelled recordings")
        ("batch", po::value(&o.batch)->default_value(o.batch), "answers per batch")
        ("explore", po::value(&o.explore)->default_value(o.explore), "active: every Nth answer a random candidate (0: off)")
        ("accept", po::value(&o.accept)->default_value(o.accept), "model answers: P >= this is y")
        ("reject", po::value(&o.reject)->default_value(o.reject), "model answers: P <= this is n")
        ("flip", po::value(&o.flip_fraction)->default_value(o.flip_fraction), "review: share of labels flipped")
        ("seed", po::value(&o.seed)->default_value(o.seed), "first batch, passive order, flips");
    rdsf::cli::add_threads_option(options, o.threads, "threads analysing and scoring the recordings");
    po::variables_map values;
    if (!rdsf::cli::parse(argc, argv, kProgram, options, values)) return 0;
    if (o.batch < 1) throw rdsf::cli::UsageError("--batch must be at least 1");
    return rdsf::bench::run_labeler_bench(o);
  });
}
