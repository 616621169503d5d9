// The table of BoostTrainingParams (core/parameter_table.hpp): rdsf-train's boosting options, recipe keys,
// --thesis values, range checks and what a model file's training.parameters records, each declared once.
// The order is --help's and the model file's. Options of the native backend alone (bins, smoothing, depth,
// learning rate, histogram subtraction) are recorded only when the backend is native; smoothing 0 is
// recorded as "auto (1/N)", histogram subtraction only when on ("on"), folds only when K-fold validation is on.
// The native backend's rows name members of RealAdaBoostSettings, the base, hence their explicit <P, type>.
#include "rdsf/classifier/boost_training.hpp"

namespace rdsf {
namespace {

using P = BoostTrainingParams;

/// `row` recorded only for the native backend, as `text` (default: the row's value).
Parameter<P> native_only(Parameter<P> row, std::function<std::optional<std::string>(const P&)> text = {}) {
  const auto get = row.get;
  return recorded_as<P>(std::move(row), [get, text](const P& p) -> std::optional<std::string> {
    if (p.backend != BoostBackend::native) return std::nullopt;
    return text ? text(p) : parameter_text(get(p));
  });
}

}  // namespace

const ParameterTable<BoostTrainingParams>& boost_training_parameters() {
  static const ParameterTable<P> table = {
      computed_parameter<P, std::string>(
          "backend", "native (Real AdaBoost, look-up tables) or opencv (cv::ml::Boost REAL stumps)",
          [](const P& p) { return p.backend.name(); },
          [](P& p, const std::string& name) {
            const BoostBackend backend(name);
            if (backend == BoostBackend::unknown) refuse_parameter("backend", "'" + name + "' is not known (native or opencv)");
            p.backend = backend;
          }),
      parameter("rounds", &P::rounds, "boosting rounds", Range::at_least(1)),
      [] {
        Parameter<P> bins = computed_parameter<P, int>(
            "bins", "native: bins per feature over [0, 1] (2-256)", [](const P& p) { return p.bins.count; },
            [](P& p, const int& count) {
              const std::string problem = Range::between(2, 256).problem(count);
              if (!problem.empty()) refuse_parameter("bins", problem);
              p.bins.count = count;
            });
        bins.record = [](const P& p) {  // the bins' range too, which is not an option
          if (p.backend != BoostBackend::native) return RecordedParameters{};
          return RecordedParameters{{"bins", parameter_text(p.bins.count)},
                                    {"bin_min", parameter_text(p.bins.min_value)},
                                    {"bin_max", parameter_text(p.bins.max_value)}};
        };
        return bins;
      }(),
      native_only(parameter<P, double>("smoothing", &P::smoothing, "native: eps of the responses (0 = 1 / training samples)",
                            Range::at_least(0)),
                  [](const P& p) { return p.smoothing > 0.0 ? parameter_text(p.smoothing) : "auto (1/N)"; }),
      native_only(parameter<P, int>("depth", &P::depth,
                            "native: levels of look-up tables per weak classifier (1 = one table as the thesis; 2-4 = trees)",
                            Range::between(1, 4), std::optional<int>(1))),
      native_only(parameter<P, double>("learning-rate", &P::learning_rate, "native: shrinkage of every response, in (0, 1]",
                            Range::above_to(0, 1), std::optional<double>(1.0))),
      native_only(computed_parameter<P, bool>(
                      "histogram-subtraction",
                      "native trees: count one child of two, the other is parent - sibling (faster; ties may break otherwise)",
                      [](const P& p) { return p.histogram_subtraction; },
                      [](P& p, const bool& on) { p.histogram_subtraction = on; }, std::nullopt, /*is_switch=*/true),
                  [](const P& p) { return p.histogram_subtraction ? std::optional<std::string>("on") : std::nullopt; }),
      parameter("calibration", &P::calibration,
                "platt (fit P(person) on the validation samples) or none (P = 1 / (1 + exp(-2 H)))", {},
                std::optional<std::string>(),
                std::function<std::string(const std::string&)>([](const std::string& c) {
                  return c == "platt" || c == "none" ? "" : "'" + c + "' is not known (platt or none)";
                })),
      recorded_as<P>(parameter("folds", &P::folds,
                               "K-fold validation by group (2-20): K models on K-1 folds of whole groups give the "
                               "validation figures and calibration of the final model, trained on all samples (0 = one "
                               "held-out fraction; early stopping and separate validation sets use one held-out split)",
                               {}, std::optional<int>(),
                               std::function<std::string(const int&)>([](const int& k) {
                                 return k == 0 || (k >= 2 && k <= 20) ? "" : "must be 0 (off) or 2-20";
                               })),
                     [](const P& p) { return p.folds > 0 ? std::optional<std::string>(parameter_text(p.folds)) : std::nullopt; }),
      recorded_as<P>(parameter<P, double>("operating-tar", &P::operating_tar,
                                          "the model states an operating point: the highest P(person) at which at "
                                          "least this share of the validation people are accepted; rdsf-detect "
                                          "reads the model there unless given --threshold (0 = none: P >= 0.5)",
                                          Range::between(0, 1)),
                     [](const P& p) {
                       return p.operating_tar > 0 ? std::optional<std::string>(parameter_text(p.operating_tar))
                                                  : std::nullopt;
                     }),
      parameter<P, double>("weight-trim", &P::weight_trim,
                "fraction of the weight trimmed per round (0 = off; OpenCV's 0.95 rate is 0.05)",
                Range::from_below(0, 1)),
      parameter("validation-fraction", &P::validation_fraction,
                "fraction of each class held out for validation (0 = none)", Range::from_below(0, 1)),
      parameter("seed", &P::seed, "seed of the subsets and the validation split"),
      parameter("report-every", &P::report_every, "rounds between the figures kept in the model file",
                Range::at_least(1)),
      parameter("early-stopping", &P::early_stopping,
                "stop after this many rounds without a better validation AUC, keep the best (0 = off)",
                Range::at_least(0)),
  };
  return table;
}

}  // namespace rdsf
