// rdsf-label: a person confirms the detector core's candidates one by one (y / n / skip / undo / quit);
// every answer is stored before the next candidate appears, and a rerun resumes where it stopped.
#include "cli/cli.hpp"
#include "label_run.hpp"

int main(int argc, char** argv) {
  return rdsf::cli::run("rdsf-label", [&] {
    namespace po = rdsf::cli::po;
    rdsf::LabelOptions o;
    rdsf::EmpiricalCalibration calibration;
    po::options_description options("rdsf-label");
    options.add_options()
        ("source", po::value(&o.session.sources)->required()->composing(),
         "frames to label (repeat for several): folder, list file, PNG, .oni, 'openni' or device URI")
        ("out", po::value(&o.out_set)->required(), "sample set to append to (created when missing)")
        ("model", po::value(&o.model), "show each candidate's score H(x) with this model (file, NAME or NAME/vN)")
        ("models-dir", po::value(&o.models_dir)->default_value(o.models_dir), "where model NAMEs are looked up")
        ("order-by-score", po::bool_switch(&o.session.order_by_score), "present a frame's candidates best score first")
        ("truth", po::value(&o.truth_csv),
         "assisted mode: boxes.csv; IoU >= 0.5 answers y, < 0.3 answers n, only the band between is asked")
        ("min-visible", po::value(&o.min_visible)->default_value(o.min_visible),
         "assisted mode: people with visible_fraction below this are don't-care (as rdsf-detect's evaluation): "
         "their candidates are asked, not answered")
        ("answers", po::value(&o.answers), "headless: read keys from this file (- = stdin) instead of a window")
        ("keep-rejected", po::bool_switch(&o.session.keep_rejected), "store 'n' answers as negatives (label 0)");
    options.add(rdsf::cli::camera_options(o.session.camera, calibration));
    options.add(rdsf::cli::detector_options(o.session.detector));
    po::variables_map values;
    const rdsf::cli::ProgramInfo info{
        "rdsf-label", "--source SRC... --out SET [--model M] [--truth boxes.csv] [--answers FILE|-] [--keep-rejected]",
        "Shows each candidate of each frame; keys: y person, n not a person, s/space skip, u/backspace undo\n"
        "(also across frames), q/Esc save and quit. Every answer is stored before the next candidate appears;\n"
        "run again on the same sources and set to resume. --answers takes the same keys as whitespace-separated\n"
        "tokens (y n s u q, space, backspace, esc; 'yyn' is three keys)."};
    if (!rdsf::cli::parse(argc, argv, info, options, values)) return 0;
    rdsf::cli::apply_calibration(o.session.camera, calibration);
    return rdsf::run_label(o);
  });
}
