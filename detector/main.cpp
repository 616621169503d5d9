// rdsf-detect: runs the detector core on every frame of a source and reports the candidates.
#include "cli/cli.hpp"
#include "detector/detect_run.hpp"

int main(int argc, char** argv) {
  return rdsf::cli::run("rdsf-detect", [&] {
    namespace po = rdsf::cli::po;
    rdsf::DetectOptions o;
    rdsf::EmpiricalCalibration calibration;
    po::options_description options("rdsf-detect");
    options.add_options()
        ("source", po::value(&o.source)->required(),
         "frames: a folder of NAME.depth.png, a list file, one PNG, an .oni file, 'openni' or a device URI")
        ("out", po::value(&o.out_csv), "write frame,candidate,x,y,w,h,depth_mm,score to this CSV")
        ("save-dir", po::value(&o.save_dir), "write NAME.candidates.png per frame (layers and boxes) here")
        ("show", po::bool_switch(&o.show), "show each frame in a window (q or Esc stops)")
        ("force", po::bool_switch(&o.force), "replace an existing --out file");
    options.add(rdsf::cli::camera_options(o.camera, calibration));
    options.add(rdsf::cli::detector_options(o.detector));
    po::variables_map values;
    const rdsf::cli::ProgramInfo info{
        "rdsf-detect", "--source SRC [--out FILE.csv] [--save-dir DIR] [--show] [options]",
        "Runs the detector core (segmentation, candidates) on every frame of SRC. Without a model every\n"
        "candidate is reported, with an empty score."};
    if (!rdsf::cli::parse(argc, argv, info, options, values)) return 0;
    rdsf::cli::apply_calibration(o.camera, calibration);
    return rdsf::run_detect(o);
  });
}
