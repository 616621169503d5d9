#include "trainer/train_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <limits>
#include <optional>
#include <set>

#include "rdsf/candidates/crop_provenance.hpp"
#include "rdsf/classifier/boosted_model.hpp"
#include "rdsf/classifier/features_read.hpp"
#include "rdsf/classifier/model_registry.hpp"
#include "cli/cli.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/dataset/recipe.hpp"
#include "trainer/ranks.hpp"
#include "rdsf/dataset/thesis_text.hpp"
#include "rdsf/pipeline/stated_options.hpp"
#include "trainer/training_samples.hpp"

namespace rdsf {
namespace {

// The recipe (when given) with the command line's overrides applied.
Recipe effective_recipe(const TrainOptions& o) {
  Recipe r;
  if (!o.recipe.empty()) {
    r = load_recipe(o.recipe, o.models_dir);
  } else {
    r.name = o.name;
  }
  // --pos / --neg replace the recipe's sets of that role.
  if (!o.pos_sets.empty()) r.pos_sets = o.pos_sets;
  if (!o.neg_sets.empty()) r.neg_sets = o.neg_sets;
  if (!o.validation_pos_sets.empty()) r.validation_pos_sets = o.validation_pos_sets;
  if (!o.validation_neg_sets.empty()) r.validation_neg_sets = o.validation_neg_sets;
  if (o.positives) r.positives = *o.positives;
  if (o.negatives) r.negatives = *o.negatives;
  BoostTrainingParams& p = r.params;
  if (o.thesis) p = with_thesis_values(boost_training_parameters(), p);
  cli::apply_overrides(boost_training_parameters(), p, o.boosting);
  p.threads = o.threads;
  validate_training_params(p);
  if (r.pos_sets.empty() || r.neg_sets.empty()) {
    throw cli::UsageError("give a --recipe, or sample sets with --pos SET and --neg SET");
  }
  if (r.validation_pos_sets.empty() != r.validation_neg_sets.empty()) {
    throw cli::UsageError("a separate validation set needs both --validation-pos and --validation-neg");
  }
  return r;
}

SampleChoice training_choice(const Recipe& r, const TrainOptions& o) {
  SampleChoice c;
  c.pos_sets = r.pos_sets;
  c.neg_sets = r.neg_sets;
  c.positives = r.positives;
  c.negatives = r.negatives;
  c.seed = r.params.seed;
  c.asked_by = o.recipe.empty() || o.positives || o.negatives ? std::string("the command line")
                                                               : "recipe " + r.name;
  if (o.feature_spec_given) c.spec = o.feature_spec;
  c.feature_pool = o.feature_pool;
  c.memory_budget_mb = o.memory_budget_mb;
  const TrainingDataParams data = effective_training_data(o);
  c.group_frames = data.group_frames;
  c.group_by = parse_group_by(data.group_by);
  c.augmentation = parse_augmentation(data.augment, data.augment_copies, r.params.seed);
  return c;
}

std::string duration_text(double seconds) {
  char text[32];
  if (seconds < 120) {
    std::snprintf(text, sizeof text, "%.0f s", seconds);
  } else {
    std::snprintf(text, sizeof text, "%.1f min", seconds / 60.0);
  }
  return text;
}

// A separate validation set must not share a group (recording and frame block) with the training rows. The
// groups are those of both sides' rows together: a block of frames named by rank (names that are no numbers)
// is only the same block when ranked among the same frames.
void check_disjoint_groups(const ChosenSamples& train, const ChosenSamples& validation, const SampleChoice& choice) {
  if (choice.group_frames <= 0 || train.origins.empty() || validation.origins.empty()) return;
  std::vector<SampleOrigin> both = train.origins;
  both.insert(both.end(), validation.origins.begin(), validation.origins.end());
  const SampleGroups groups = sample_groups(both, choice.group_frames, choice.group_by);
  std::vector<char> in_train(groups.names.size(), 0);
  for (std::size_t i = 0; i < train.origins.size(); ++i) in_train[groups.group[i]] = 1;
  std::set<std::string> shared;
  for (std::size_t i = train.origins.size(); i < both.size(); ++i) {
    if (in_train[groups.group[i]]) shared.insert(groups.names[groups.group[i]]);
  }
  if (!shared.empty()) {
    throw Error("the validation sets share " + std::to_string(shared.size()) + " groups with the training sets (e.g. '" +
                *shared.begin() + "': the same recording and frames): validate on other recordings");
  }
}

// What every rank of a data-parallel run must have alike: the effective recipe and options, one per line.
std::string options_text(const Recipe& r, const TrainOptions& o) {
  std::string text;
  auto line = [&text](const std::string& name, const std::string& value) { text += name + " " + value + "\n"; };
  auto list = [](const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& item : items) out += item + " ";
    return out;
  };
  const BoostTrainingParams& p = r.params;
  line("recipe", o.recipe + " " + r.name);
  line("pos", list(r.pos_sets));
  line("neg", list(r.neg_sets));
  line("validation", list(r.validation_pos_sets) + "/ " + list(r.validation_neg_sets));
  line("counts", std::to_string(r.positives) + " " + std::to_string(r.negatives));
  line("boosting", p.backend.name() + " rounds " + std::to_string(p.rounds) + " bins " + std::to_string(p.bins.count) +
                       " depth " + std::to_string(p.depth) + " folds " + std::to_string(p.folds) + " seed " +
                       std::to_string(p.seed) + " early " + std::to_string(p.early_stopping) + " report " +
                       std::to_string(p.report_every) + " calibration " + p.calibration);
  char numbers[160];
  std::snprintf(numbers, sizeof numbers, "%.17g %.17g %.17g %.17g", p.learning_rate, p.smoothing,
                p.validation_fraction, p.weight_trim);
  line("numbers", numbers);
  const TrainingDataParams data = effective_training_data(o);
  line("groups", std::to_string(data.group_frames) + " " + data.group_by);
  line("augment", data.augment + " " + std::to_string(data.augment_copies) + (o.thesis ? " thesis" : ""));
  line("features", (o.feature_spec_given ? o.feature_spec.canonical() : std::string("the sets'")) + " pool " +
                       std::to_string(o.feature_pool) + " budget " + std::to_string(o.memory_budget_mb));
  line("name", o.name + " in " + o.models_dir + " init " + o.init);
  return text;
}

// What every rank must have read alike: the feature spec and every set's manifest and counts.
std::string data_text(const ChosenSamples& train, const ChosenSamples& validation) {
  std::string text = "feature spec " + train.spec.hash() + " rows " + std::to_string(train.labels.size()) + " + " +
                     std::to_string(validation.labels.size()) + "\n";
  for (const ChosenSamples* c : {&train, &validation}) {
    for (const SampleSetUse& u : c->sets) {
      text += u.role + " " + u.path + " manifest " + u.manifest_hash + " available " + std::to_string(u.available) +
              " used " + std::to_string(u.used) + "\n";
    }
  }
  return text;
}

/// --detection-options read: every analyser option at its default but the NAME=VALUE words given
/// (pipeline/stated_options.hpp); none for no words. Throws cli::UsageError naming the word.
RecordedParameters stated_detection_options(const std::vector<std::string>& words) {
  if (words.empty()) return {};
  RecordedParameters given;
  for (const std::string& word : words) {
    if (word == "defaults" && words.size() == 1) break;
    const std::size_t eq = word.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw cli::UsageError("--detection-options '" + word + "': give NAME=VALUE (an analyser option) or 'defaults'");
    }
    given.emplace_back(parameter_key(cli::canonical_option_name(word.substr(0, eq))), word.substr(eq + 1));
  }
  try {
    return stated_options(given);
  } catch (const Error& e) {
    throw cli::UsageError("--detection-options: " + std::string(e.what()));
  }
}

/// What the command line asks for, checked: the effective recipe, the model's name, the --provenance pairs
/// and the detection options stated.
struct TrainingPlan {
  std::vector<std::pair<std::string, std::string>> provenance;
  RecordedParameters detection_options;
  Recipe recipe;
  std::string name;
};

/// The checks that need the recipe (and, under mpirun, every rank's options), in this order: --provenance,
/// the recipe and its overrides, the ranks' agreement and what data-parallel training allows,
/// --group-frames, the model name. Before any sample is read.
TrainingPlan plan_training(const TrainOptions& o, const RowShards& shards) {
  TrainingPlan plan;
  for (const std::string& kv : o.provenance) {
    const std::size_t eq = kv.find('=');
    const std::string key = kv.substr(0, eq);
    if (eq == std::string::npos || key.empty() ||
        key.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") != std::string::npos ||
        kv.find_first_of("\n\r") != std::string::npos) {
      throw cli::UsageError("--provenance '" + kv + "': give KEY=VALUE, KEY of a-z, 0-9 and _, one line");
    }
    plan.provenance.emplace_back(key, kv.substr(eq + 1));
  }
  plan.detection_options = stated_detection_options(o.detection_options);
  plan.recipe = effective_recipe(o);
  const BoostTrainingParams& p = plan.recipe.params;
  if (shards.distributed()) {
    check_ranks_agree(shards, "options", options_text(plan.recipe, o));
    if (p.backend != BoostBackend::native || p.weight_trim > 0.0 || p.histogram_subtraction) {
      throw cli::UsageError("data-parallel training (" + std::to_string(shards.size()) +
                            " ranks) needs the native backend without --weight-trim and --histogram-subtraction");
    }
  }
  plan.name = o.name.empty() ? plan.recipe.name : o.name;
  if (plan.name.empty()) throw cli::UsageError("ad hoc training needs a model name: give --name NAME");
  validate_model_name(plan.name);
  return plan;
}

/// Continued training: the --init model, read (and its bins checked) before any sample is.
std::optional<BoostedModel> read_init_model(const TrainOptions& o, const Recipe& recipe, const RowShards& shards) {
  std::optional<BoostedModel> init;
  if (o.init.empty()) return init;
  on_every_rank(shards, "reading the --init model", [&] { init = BoostedModel::load(o.init, o.models_dir); });
  const bool bins_given = std::any_of(o.boosting.begin(), o.boosting.end(), [](const auto& g) { return g.first == "bins"; });
  if (bins_given && recipe.params.bins.count != init->bins().count) {
    throw cli::UsageError("--bins " + std::to_string(recipe.params.bins.count) + " differs from the --init model's " +
                          std::to_string(init->bins().count) + " (continued training keeps its bins)");
  }
  return init;
}

/// The separate validation sets, read like the training sets (`train_choice`, `train`): the same spec, crops,
/// features and validation groups.
ChosenSamples read_validation(const TrainOptions& o, const Recipe& recipe, const SampleChoice& train_choice,
                              const ChosenSamples& train, const RowShards& shards) {
  SampleChoice v;
  v.pos_sets = recipe.validation_pos_sets;
  v.neg_sets = recipe.validation_neg_sets;
  v.seed = recipe.params.seed;
  v.asked_by = "validation";
  v.role_prefix = "validation-";
  v.spec = train.spec;          // the same spec, crops cut the same way ...
  v.crops = train.crops;
  v.columns = train.columns;    // ... and the same features as training
  v.feature_pool = std::numeric_limits<std::size_t>::max();  // all of them when training has all
  v.group_frames = train_choice.group_frames;
  v.group_by = train_choice.group_by;
  v.shard = shards.rank();
  v.shards = shards.size();
  ChosenSamples validation;
  on_every_rank(shards, "reading its share of the validation sets",
                [&] { validation = choose_samples(v, std::cerr, o.threads); });
  check_disjoint_groups(train, validation, v);
  return validation;
}

/// Every rank reads its share of the training (and validation) rows; the ranks must agree on what they read.
/// A feature pool holds every feature the --init model reads (its scores come from the rows).
void read_samples(const TrainOptions& o, const Recipe& recipe, const RowShards& shards,
                  const std::optional<BoostedModel>& init, ChosenSamples& train, ChosenSamples& validation) {
  SampleChoice train_choice = training_choice(recipe, o);
  if (init) train_choice.required_features = features_read(*init);
  train_choice.shard = shards.rank();
  train_choice.shards = shards.size();
  on_every_rank(shards, "reading its share of the training sets",
                [&] { train = choose_samples(train_choice, std::cerr, o.threads); });
  if (!recipe.validation_pos_sets.empty()) validation = read_validation(o, recipe, train_choice, train, shards);
  check_ranks_agree(shards, "sample sets or feature spec", data_text(train, validation));
  if (shards.distributed()) {
    std::cerr << "rdsf-train: " << shards.size() << " ranks; rank 0 holds " << train.rows.rows << " of the "
              << train.labels.size() << " training rows\n";
  }
  const std::size_t positives = static_cast<std::size_t>(std::count(train.labels.begin(), train.labels.end(), 1));
  std::cerr << "rdsf-train: " << positives << " positives, " << train.labels.size() - positives
            << " negatives x " << train.rows.cols << " features\n";
  if (recipe.params.backend == BoostBackend::opencv) {
    std::cerr << "rdsf-train: OpenCV trains all rounds in one call: no progress until it is done (about 16-33 s "
                 "per round at 28,000 samples)\n";
  }
}

/// One line per reported round on stderr.
TrainingProgressFn round_printer(const FeatureSpec& spec) {
  return [spec](const TrainingProgress& p) {
    char line[256], fold[32] = "";
    if (p.folds > 0 && p.fold <= p.folds) std::snprintf(fold, sizeof fold, "fold %d/%d  ", p.fold, p.folds);
    if (p.folds > 0 && p.fold > p.folds) std::snprintf(fold, sizeof fold, "final model  ");
    int n = std::snprintf(line, sizeof line, "%sround %d/%d  feature %d (%s)  train err %.4f", fold, p.round, p.rounds,
                          p.feature, spec.describe_feature(p.feature).c_str(), p.train_error);
    if (p.validation_error && n > 0 && n < static_cast<int>(sizeof line)) {
      n += std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), "  val err %.4f  AUC %.4f",
                         *p.validation_error, *p.validation_auc);
    }
    std::cerr << "rdsf-train: " << line << "  " << (p.round_s < 1 ? std::to_string(static_cast<int>(p.round_s * 1000)) + " ms"
                                                                  : duration_text(p.round_s))
              << "/round  " << duration_text(p.left_s) << " left\n";
  };
}

/// The rows' groups, augmentation marks and (under mpirun) owners, for the boosting.
TrainingRowInfo row_info(const ChosenSamples& train, const ChosenSamples& validation, const RowShards& shards) {
  TrainingRowInfo info;
  info.groups = train.groups;
  info.augmented = train.augmented;
  if (shards.distributed()) {
    info.owners = RowOwners(&shards, train.owner);
    if (!validation.labels.empty()) info.validation_owners = RowOwners(&shards, validation.owner);
  }
  return info;
}

/// Continued training: checks the --init model against the sets and starts `params` from it; returns the
/// reference recorded in the new model ("NAME/vN (path)").
std::string continue_from(const BoostedModel& init, const TrainOptions& o, const ChosenSamples& train,
                          BoostTrainingParams& params) {
  const std::string what = init.path().empty() ? o.init : init.path();
  if (init.feature_spec() != train.spec) {
    throw Error(what + ": --init model reads feature spec " + init.feature_spec().name() + " (" +
                init.feature_spec().hash() + "), the sets hold " + train.spec.name() + " (" + train.spec.hash() + ")");
  }
  const std::string crops = crop_provenance_mismatch(init.training().crops, "the --init model's crops", train.crops,
                                                     "the sets' crops");
  if (!crops.empty()) throw Error(what + ": " + crops);
  params.bins = init.bins();
  params.init = init.weak_classifiers();
  const std::string reference = model_reference(init) + " (" + what + ")";
  std::cerr << "rdsf-train: continuing " << reference << ": " << params.init.size() << " weak classifiers, then "
            << params.rounds << " new rounds\n";
  return reference;
}

/// The detection options the model states (stated_options.hpp): --detection-options when given, else the
/// analyser options every training and validation set records alike (the candidates it learned), else the
/// --init model's, else none. A set's options this build does not know are not stated (a warning says so).
RecordedParameters stated_by_model(const TrainingPlan& plan, const ChosenSamples& train, const ChosenSamples& validation,
                                   const std::optional<BoostedModel>& init) {
  if (!plan.detection_options.empty()) return plan.detection_options;
  const bool agree = validation.labels.empty() || validation.analyser_options == train.analyser_options;
  if (agree && !train.analyser_options.empty()) {
    try {
      return stated_options(train.analyser_options);
    } catch (const Error& e) {
      std::cerr << "rdsf-train: warning: the sets' analyser options are not stated (" << e.what() << ")\n";
    }
  }
  return init ? init->detection_options() : RecordedParameters{};
}

/// Writes where the model came from into its training record.
void record_provenance(TrainingRecord& record, const TrainOptions& o, const TrainingPlan& plan,
                       const ChosenSamples& train, const ChosenSamples& validation, const std::string& init_reference) {
  const Recipe& recipe = plan.recipe;
  record.recipe = o.recipe.empty() ? "ad hoc" : recipe.name + " (" + recipe.path + ")";
  record.sample_sets = train.sets;
  record.sample_sets.insert(record.sample_sets.end(), validation.sets.begin(), validation.sets.end());
  record.crops = known_of(train.crops, validation.crops);
  record.parameters.insert(record.parameters.begin(), {"positives_wanted", std::to_string(recipe.positives)});
  record.parameters.insert(record.parameters.begin() + 1, {"negatives_wanted", std::to_string(recipe.negatives)});
  record.parameters.emplace_back("feature_spec", train.spec.option_text());
  record.parameters.emplace_back("feature_pool", train.columns.empty() ? std::string("all")
                                                                       : std::to_string(train.columns.size()));
  const TrainingDataParams data = effective_training_data(o);
  record.parameters.emplace_back("group_frames", std::to_string(data.group_frames));
  record.parameters.emplace_back("group_by", data.group_by);
  record.parameters.emplace_back("augmentation",
                                 parse_augmentation(data.augment, data.augment_copies, recipe.params.seed).describe());
  if (!init_reference.empty()) record.parameters.emplace_back("init", init_reference);
  record.parameters.insert(record.parameters.end(), plan.provenance.begin(), plan.provenance.end());
}

/// The model's size, why it stopped and its validation figures, on stderr.
void report_model(const BoostedModel& model, const std::string& path) {
  const TrainingRecord& record = model.training();
  const ValidationFigures& v = record.validation;
  std::fprintf(stderr, "rdsf-train: %zu weak classifiers (%s); validation: %s\n", model.weak_classifiers().size(),
               record.stopped.c_str(), v.source.c_str());
  if (v.positives > 0 && v.negatives > 0) {
    std::fprintf(stderr, "rdsf-train: validation AUC %.4f, TAR %.3f at FAR 1%%, %.3f at FAR 5%%, error %.4f\n",
                 v.summary.auc, v.summary.tar_at_far_1, v.summary.tar_at_far_5, v.summary.error_rate);
    const ScoreCalibration& c = model.calibration();
    std::fprintf(stderr, "rdsf-train: calibration %s: P(person) = 1 / (1 + exp(-(%.4f H + %.4f)))", c.method.c_str(),
                 c.a, c.b);
    for (const ProbabilityPoint& p : v.by_probability) {
      if (std::abs(p.probability - 0.5) < 1e-9) {
        std::fprintf(stderr, "; at P >= 0.5: TAR %.3f, FAR %.3f", p.tar, p.far);
      }
    }
    std::fprintf(stderr, "\n");
  }
  if (model.operating_point()) {
    std::fprintf(stderr, "rdsf-train: operating point P(person) >= %.2f: %s\n", model.operating_point()->probability,
                 model.operating_point()->rule.c_str());
    const double far = model.operating_point()->validation_far;
    if (far > kWeakOperatingFar) {
      std::fprintf(stderr,
                   "rdsf-train: warning: at its operating point the model accepts %.1f %% of its validation "
                   "non-people (FAR %.3f > %.2f): it tells people from clutter poorly; more rounds or samples help\n",
                   100.0 * far, far, kWeakOperatingFar);
    }
  }
  std::cerr << "rdsf-train: wrote " << path << "\n";
}

}  // namespace

TrainingDataParams effective_training_data(const TrainOptions& o) {
  TrainingDataParams data;
  if (o.thesis) data = with_thesis_values(training_data_parameters(), data);
  cli::apply_overrides(training_data_parameters(), data, o.training_data);
  try {
    parse_augmentation(data.augment, data.augment_copies, 0);  // the copies need an augmentation that varies
  } catch (const Error& e) {
    throw cli::UsageError(e.what());
  }
  return data;
}

void check_options(const TrainOptions& o, bool ranks) {
  const int modes = static_cast<int>(!o.inspect.empty()) + static_cast<int>(!o.export_text.empty());
  if (modes > 1) throw cli::UsageError("give either --inspect or --export-text, not both");
  if (modes > 0 && ranks) throw cli::UsageError("--inspect and --export-text run in one process, not under mpirun");
  if (!o.inspect.empty()) return;
  if (o.recipe.empty() && (o.pos_sets.empty() || o.neg_sets.empty())) {
    throw cli::UsageError("give --recipe NAME, or --pos SET and --neg SET (see rdsf-train --help)");
  }
  effective_training_data(o);  // a refused --group-by or --augment is a usage error before anything is read
}

int run_train(const TrainOptions& o) { return run_train(o, RowShards{}); }

int run_train(const TrainOptions& o, const RowShards& shards) {
  const TrainingPlan plan = plan_training(o, shards);
  const Recipe& recipe = plan.recipe;
  std::cerr << "rdsf-train: model " << plan.name << " (next version v" << latest_model_version(o.models_dir, plan.name) + 1
            << " under " << o.models_dir << "), " << recipe.params.backend.name() << " backend, " << recipe.params.rounds
            << " rounds\n";
  const std::optional<BoostedModel> init = read_init_model(o, recipe, shards);
  ChosenSamples train, validation;
  read_samples(o, recipe, shards, init, train, validation);

  const bool separate = !validation.labels.empty();
  const TrainingRowInfo info = row_info(train, validation, shards);
  BoostTrainingParams params = recipe.params;
  params.feature_spec = train.spec;
  params.feature_columns = train.columns;
  const std::string init_reference = init ? continue_from(*init, o, train, params) : std::string();
  BoostedModel model = train_boosted_model(train.rows, train.labels, params, round_printer(train.spec),
                                           separate ? &validation.rows : nullptr,
                                           separate ? &validation.labels : nullptr, info);
  record_provenance(model.training(), o, plan, train, validation, init_reference);
  model.set_detection_options(stated_by_model(plan, train, validation, init));

  std::string path;  // rank 0 writes the model; every rank learns whether it could
  on_every_rank(shards, "writing the model", [&] {
    if (shards.rank() == 0) path = save_new_model_version(model, plan.name, o.models_dir);
  });
  if (shards.rank() != 0) return 0;
  report_model(model, path);
  return 0;
}

int run_export_text(const TrainOptions& o) {
  const Recipe recipe = effective_recipe(o);
  SampleChoice choice = training_choice(recipe, o);
  choice.augmentation = CropAugmentation{};  // the samples as they are, not training-time copies
  choice.feature_pool = std::numeric_limits<std::size_t>::max();  // the text format holds whole vectors
  const ChosenSamples samples = choose_samples(choice, std::cerr, o.threads);
  const std::int64_t lines = write_thesis_text(samples.rows, samples.labels, o.export_text, o.force);
  std::cerr << "rdsf-train: wrote " << lines << " samples to " << o.export_text << "\n";
  return 0;
}

}  // namespace rdsf
