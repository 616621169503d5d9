// rdsf-detect: runs the whole system (candidates, RDSF, classifier, tracking) on every frame of a source,
// and evaluates models against ground truth.
#include "cli/cli.hpp"
#include "detector/detect_run.hpp"

int main(int argc, char** argv) {
  return rdsf::cli::run("rdsf-detect", [&] {
    namespace po = rdsf::cli::po;
    rdsf::DetectOptions o;
    rdsf::EmpiricalCalibration calibration;
    std::string thresholds;
    po::options_description options("rdsf-detect");
    options.add_options()
        ("source", po::value(&o.source)->required(),
         "frames: a folder of NAME.depth.png, a list file, one PNG, an .oni file, 'openni' or a device URI")
        ("model", po::value(&o.models)->composing(),
         "model file, NAME (newest version) or NAME/vN; repeat to compare models in the evaluation")
        ("models-dir", po::value(&o.models_dir)->default_value(o.models_dir), "where model NAMEs are looked up")
        ("threshold", po::value(&o.pipeline.threshold_classifier)->default_value(o.pipeline.threshold_classifier),
         "threshold_classifier: a candidate is a person when H(x) >= this")
        ("out", po::value(&o.out_csv), "write one row per candidate to this CSV")
        ("save-dir", po::value(&o.save_dir), "write NAME.detections.png per frame here")
        ("show", po::bool_switch(&o.show), "show each frame in a window (q or Esc stops)")
        ("truth", po::value(&o.truth_csv), "boxes.csv of the source: evaluate the models (needs --report-dir)")
        ("report-dir", po::value(&o.report_dir), "write metrics.csv, summary.txt, roc.png, det.png here")
        ("thresholds", po::value(&thresholds),
         "evaluation sweep: 40,20,0 or from:to:step (default the thesis's 40 20 10 0 -5 ... -40 -60)")
        ("min-visible", po::value(&o.min_visible)->default_value(o.min_visible),
         "evaluation: people with visible_fraction below this are don't-care (no miss, no false positive)")
        ("force", po::bool_switch(&o.force), "replace an existing --out file or report");
    options.add(rdsf::cli::camera_options(o.camera, calibration));
    options.add(rdsf::cli::detector_options(o.pipeline.detector));
    options.add(rdsf::cli::tracking_options(o.pipeline.tracking));
    po::variables_map values;
    const rdsf::cli::ProgramInfo info{
        "rdsf-detect", "--source SRC [--model M] [--out FILE.csv] [--save-dir DIR] [--truth boxes.csv --report-dir DIR]",
        "Runs the detector core on every frame of SRC. Without a model every candidate is reported unscored;\n"
        "with one, candidates are scored (H(x)), those >= --threshold are people, and people are tracked.\n"
        "With --truth, every --model is evaluated over a threshold sweep as in the thesis."};
    if (!rdsf::cli::parse(argc, argv, info, options, values)) return 0;
    rdsf::cli::apply_calibration(o.camera, calibration);
    o.feature_spec_given = !values["feature-spec"].defaulted();
    o.thresholds = rdsf::cli::parse_thresholds(thresholds);
    return rdsf::run_detect(o);
  });
}
