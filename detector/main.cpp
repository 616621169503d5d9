// rdsf-detect: runs the whole system (candidates, RDSF, classifier, tracking) on every frame of a source,
// and evaluates models against ground truth.
#include "cli/cli.hpp"
#include "cli/common_options.hpp"
#include "detector/detect_run.hpp"
#include "rdsf/evaluation/threshold_sweep.hpp"

const rdsf::cli::ProgramInfo kProgram{
    "rdsf-detect", "--source SRC [--model M] [--out FILE.csv] [--save-dir DIR] [--truth boxes.csv --report-dir DIR]",
    "Runs the frame analyser on every frame of SRC. Without a model every candidate is reported unscored;\n"
    "with one, candidates are scored (H(x) and the calibrated P(person)), those with P >= --threshold are\n"
    "people, and people are tracked. With --truth, every --model is evaluated: exact ROC and DET curves,\n"
    "the thesis's tables at probability thresholds, and the classifier's own figures on the candidates."};

int main(int argc, char** argv) {
  return rdsf::cli::run(kProgram.name, [&] {
    namespace po = rdsf::cli::po;
    rdsf::DetectOptions o;
    std::string thresholds;
    po::options_description options(kProgram.name);
    options.add_options()
        ("source", po::value(&o.source)->required(),
         "frames: a folder of NAME.depth.png, a list file, one PNG, an .oni file, 'openni', a device URI or a ROS 1 "
         ".bag")
        ("model", po::value(&o.models)->composing(),
         "model file, NAME (newest version) or NAME/vN; repeat to compare models in the evaluation. Default: the "
         "shipped default model 'people' (synthetic data only; see README), unless --candidates-only")
        ("candidates-only", po::bool_switch(&o.candidates_only),
         "without --model: report every candidate unscored instead of running the default model");
    rdsf::cli::add_models_dir_option(options, o.models_dir);
    rdsf::cli::add_decision_options(options, o.pipeline);
    options.add_options()
        ("out", po::value(&o.out_csv), "write one row per candidate to this CSV")
        ("save-dir", po::value(&o.save_dir), "write NAME.detections.png per frame here")
        ("show", po::bool_switch(&o.show), "show each frame in a window (q or Esc stops)")
        ("truth", po::value(&o.truth_csv),
         "boxes.csv of the source: evaluate the models (needs --report-dir); without a model, count the people "
         "with a candidate")
        ("report-dir", po::value(&o.report_dir),
         ("write " + std::string(rdsf::kEvaluationReportFiles) + " here").c_str())
        ("thresholds", po::value(&thresholds),
         "evaluation tables at these P(person) thresholds: 0.3,0.5,0.7 or from:to:step (default 0.01 0.02 0.05 "
         "0.1 ... 0.95 0.98 0.99); the ROC and DET curves are exact (every distinct score)")
        ("force", po::bool_switch(&o.force), "replace an existing --out file or report");
    rdsf::cli::add_evaluation_options(options, o.min_visible, o.clip_frames);
    rdsf::cli::add_threads_option(options, o.threads, "threads analysing frames",
                                  "tracking stays in frame order, results do not depend on it");
    options.add_options()
        ("frames", po::value(&o.max_frames)->default_value(o.max_frames),
         "stop after this many frames (0: every frame; a live device sends frames until stopped)")
        ("live", po::bool_switch(&o.live),
         "live mode: frames are analysed as they arrive, at most one waiting per thread (a late frame is dropped, "
         "the newest kept); prints drops and latency percentiles. Not with --show or --truth")
        ("fps", po::value(&o.fps)->default_value(o.fps),
         "--live with a source that is not a device (folder, .oni): deliver its frames at this rate");
    rdsf::cli::CameraOptions camera(options, o.camera, &o.frames);
    options.add(rdsf::cli::analyser_options(o.pipeline.analyser));
    options.add(rdsf::cli::background_options(o.background, o.pipeline.analyser.background_margins));
    options.add(rdsf::cli::tracking_options(o.pipeline.tracking));
    po::variables_map values;
    if (!rdsf::cli::parse(argc, argv, kProgram, options, values, camera)) return 0;
    o.feature_spec_given = !values["feature-spec"].defaulted();
    o.pipeline.analyser_given = rdsf::cli::given_analyser_options(values);
    o.thresholds = thresholds.empty() ? rdsf::default_probability_thresholds() : rdsf::cli::parse_thresholds(thresholds);
    rdsf::check_options(o);
    return rdsf::run_detect(o);
  });
}
