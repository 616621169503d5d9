// rdsf-review: a grid of a sample set's crops with their labels, most suspicious first under a model (or by
// origin or source); keys flip a label, retract a sample, open its frame, page. Every change is on disk
// before the next key.
#include "cli/cli.hpp"
#include "cli/common_options.hpp"
#include "review_run.hpp"

const rdsf::cli::ProgramInfo kProgram{
    "rdsf-review", "--set SET [--model M | --folds K] [--sort suspicion|origin|source] [--keys FILE|-]",
    "Shows the set's samples as a grid of depth and colour crops with their labels. Keys: f flip the selected\n"
    "sample's label (the corrected sample is appended, the old one retracted), x/Delete retract it, o open the\n"
    "frame it came from, arrows or h j k l move, n/space/PageDown and p/b/PageUp page, q/Esc quit. Every change\n"
    "is saved before the next key. --keys takes the same keys as tokens (f x o h j k l n p q, right left down\n"
    "up space pagedown pageup delete esc)."};

int main(int argc, char** argv) {
  return rdsf::cli::run(kProgram.name, [&] {
    namespace po = rdsf::cli::po;
    rdsf::ReviewOptions o;
    po::options_description options(kProgram.name);
    options.add_options()
        ("set", po::value(&o.set)->required(), "the sample set to review");
    rdsf::cli::add_model_option(options, o.model, "score every sample with this model");
    rdsf::cli::add_models_dir_option(options, o.models_dir);
    options.add_options()
        ("sort", po::value(&o.sort), "suspicion (the default with --model: the model's disagreement with the label), "
                                     "origin (the default without) or source")
        ("folds", po::value(&o.folds)->default_value(o.folds),
         "without --model: score each sample out of fold, with this many models trained here on the set's other "
         "groups (5 finds 86% of planted label errors in the first 5% shown, docs/review.md; 0 = off)")
        ("list", po::value(&o.list)->default_value(o.list), "print the first N samples of the order first (position, id, label, P, origin)")
        ("columns", po::value(&o.columns)->default_value(o.columns), "samples per row")
        ("rows", po::value(&o.rows)->default_value(o.rows), "rows per page")
        ("keys", po::value(&o.keys), "headless: read keys from this file (- = stdin) instead of a window");
    po::variables_map values;
    if (!rdsf::cli::parse(argc, argv, kProgram, options, values)) return 0;
    if (o.columns < 1 || o.rows < 1 || o.columns > 20 || o.rows > 20) {
      throw rdsf::cli::UsageError("--columns and --rows must be 1 to 20");
    }
    if (!o.sort.empty() && o.sort != "suspicion" && o.sort != "origin" && o.sort != "source") {
      throw rdsf::cli::UsageError("--sort must be suspicion, origin or source");
    }
    if (o.sort == "suspicion" && o.model.empty() && o.folds < 2) {
      throw rdsf::cli::UsageError("--sort suspicion needs --model or --folds");
    }
    if (o.folds == 1 || o.folds < 0 || o.folds > 20) throw rdsf::cli::UsageError("--folds must be 0 (off) or 2 to 20");
    if (o.folds > 0 && !o.model.empty()) throw rdsf::cli::UsageError("give --model or --folds, not both");
    return rdsf::run_review(o);
  });
}
