// rdsf-train's command-line options, bound to TrainOptions.
#include "trainer/train_options.hpp"

#include "cli/common_options.hpp"

namespace rdsf {
namespace {

namespace po = cli::po;

// Binds an optional override: set only when the option was given.
template <typename T>
po::typed_value<T>* optional_into(std::optional<T>& target) {
  return po::value<T>()->notifier([&target](const T& v) { target = v; });
}

}  // namespace

po::options_description train_options(TrainOptions& o) {
  po::options_description what("What to train on");
  what.add_options()
      ("recipe", po::value(&o.recipe), "recipe NAME (models/recipes/NAME.yml: tree, tree2, hugeTree, treeLast) or file")
      ("pos", po::value(&o.pos_sets)->multitoken(), "sample set(s) whose positives to use (replaces the recipe's)")
      ("neg", po::value(&o.neg_sets)->multitoken(), "sample set(s) whose negatives to use (replaces the recipe's)")
      ("validation-pos", po::value(&o.validation_pos_sets)->multitoken(),
       "separate validation set(s) for positives (instead of a held-out fraction)")
      ("validation-neg", po::value(&o.validation_neg_sets)->multitoken(), "separate validation set(s) for negatives")
      ("positives", optional_into(o.positives),
       "positives to take (seeded subset; 0 = all). Default: the recipe's, else all")
      ("negatives", optional_into(o.negatives),
       "negatives to take (seeded subset; 0 = all). Default: the recipe's, else all")
      ("name", po::value(&o.name), "model name (default: the recipe's name); saved as MODELS/NAME/vN.yml");
  cli::add_models_dir_option(what, o.models_dir, cli::ModelsDirUse::look_up_and_save,
                             "; its recipes/NAME.yml are the recipes of --recipe NAME");
  what.add_options()
      ("init", po::value(&o.init),
       "continue training MODEL (file, NAME or NAME/vN, e.g. the shipped 'people') on the given sets: --rounds "
       "more weak classifiers after its own, its bins; the new model holds both. Default: none (from nothing)")
      ("provenance", po::value(&o.provenance)->composing(),
       "KEY=VALUE recorded among the model file's training parameters (repeat; KEY of a-z, 0-9 and _), e.g. "
       "the room and answers rdsf-adapt trained on")
      ("detection-options", po::value(&o.detection_options)->multitoken()->composing(),
       "NAME=VALUE ... (analyser options, e.g. hole-gap=20) or 'defaults': the model states every candidate and "
       "segmentation option, at these values and this build's defaults for the rest, and detectors take them "
       "for the options their user does not give. Default: the options every sample set records alike (rdsf-mine "
       "and rdsf-label record theirs), else the --init model's, else none stated");
  po::options_description how("Boosting (default: the recipe's value, else the one shown)");
  cli::add_override_options(how, boost_training_parameters(), BoostTrainingParams{}, o.boosting);
  how.add_options()
      ("thesis", po::bool_switch(&o.thesis),
       "the thesis's weak learners: depth 1, learning rate 1, no augmentation (options given explicitly still win)");
  cli::add_override_options(how, training_data_parameters(), TrainingDataParams{}, o.training_data);
  cli::add_threads_option(how, o.threads, "threads for features and histograms");
  how.add_options()
      ("feature-pool", po::value(&o.feature_pool)->default_value(o.feature_pool),
       "train on a seeded pool of this many of the spec's features (0 = all when the rows fit --memory-budget-mb, "
       "else as many as fit; rdsf-rect has 120,786)")
      ("memory-budget-mb", po::value(&o.memory_budget_mb)->default_value(o.memory_budget_mb),
       "--feature-pool 0: memory for the feature rows and their bins (5 bytes per sample and feature)");
  po::options_description features = cli::feature_spec_options(o.feature_spec);
  po::options_description other("Instead of training");
  other.add_options()
      ("inspect", po::value(&o.inspect), "print a model's header, figures and most used features (file, NAME or NAME/vN)")
      ("top", po::value(&o.top)->default_value(o.top), "--inspect: features to list")
      ("export-text", po::value(&o.export_text),
       "write the chosen samples to this file in the thesis's text format (label f1 ... f8128)")
      ("force", po::bool_switch(&o.force), "--export-text may replace an existing file");
  po::options_description options;
  options.add(what).add(how).add(features).add(other);
  return options;
}

}  // namespace rdsf
