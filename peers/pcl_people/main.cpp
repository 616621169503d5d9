// rdsf-pcl-people: the peer row of the quality report. PCL's ground-based people detector on frames with
// colour, the floor fitted per recording, written as rdsf-detect's CSV and evaluated with its figures.
#include "cli/cli.hpp"
#include "cli/common_options.hpp"
#include "pcl_people_run.hpp"
#include "rdsf/evaluation/threshold_sweep.hpp"

#ifndef RDSF_PCL_SVM_FILE
#define RDSF_PCL_SVM_FILE ""
#endif

const rdsf::cli::ProgramInfo kProgram{
    "rdsf-pcl-people", "--source SRC [--out FILE.csv] [--truth boxes.csv --report-dir DIR]",
    "Runs PCL's ground-based people detector (pcl::people::GroundBasedPeopleDetectionApp with PCL's HOG+SVM\n"
    "file) on frames with colour; the floor is fitted per recording by RANSAC on the depth points (the lowest\n"
    "near-horizontal plane). Writes rdsf-detect's CSV and, with --truth, rdsf-detect's evaluation report."};

int main(int argc, char** argv) {
  return rdsf::cli::run(kProgram.name, [&] {
    namespace po = rdsf::cli::po;
    rdsf::peers::PclPeopleOptions o;
    o.svm = RDSF_PCL_SVM_FILE;
    po::options_description options(kProgram.name);
    options.add_options()
        ("source", po::value(&o.source)->required(), "frames with colour: a folder of NAME.depth.png and NAME.rgb.png, or a list file")
        ("svm", po::value(&o.svm)->default_value(o.svm), "PCL's HOG+SVM file (peers/pcl_people/data: Debian does not ship it)")
        ("out", po::value(&o.out_csv), "write one row per PCL person cluster to this CSV (rdsf-detect's format)")
        ("truth", po::value(&o.truth_csv), "boxes.csv of the source: evaluate (needs --report-dir)")
        ("report-dir", po::value(&o.report_dir), ("write " + std::string(rdsf::kEvaluationReportFiles) + " here").c_str())
        ("force", po::bool_switch(&o.force), "replace an existing --out file or report")
        ("min-confidence", po::value(&o.min_confidence)->default_value(o.min_confidence), "a cluster is a person when its HOG+SVM confidence >= this (PCL's app: -1.5)")
        ("min-height", po::value(&o.min_height_m)->default_value(o.min_height_m), "smallest person cluster height, m")
        ("max-height", po::value(&o.max_height_m)->default_value(o.max_height_m), "largest person cluster height, m")
        ("voxel-size", po::value(&o.voxel_size_m)->default_value(o.voxel_size_m), "voxel grid leaf, m")
        ("ground-max-tilt", po::value(&o.ground.max_tilt_deg)->default_value(o.ground.max_tilt_deg), "the floor's normal within this of the camera's y axis, degrees");
    rdsf::cli::add_evaluation_options(options, o.min_visible, o.clip_frames);
    rdsf::cli::CameraOptions camera(options, o.camera);
    po::variables_map values;
    if (!rdsf::cli::parse(argc, argv, kProgram, options, values, camera)) return 0;
    if (o.out_csv.empty() && o.truth_csv.empty()) throw rdsf::cli::UsageError("nothing to do: give --out FILE.csv or --truth with --report-dir");
    if (o.truth_csv.empty() != o.report_dir.empty()) throw rdsf::cli::UsageError("--truth and --report-dir go together");
    if (!(o.min_height_m > 0 && o.max_height_m > o.min_height_m)) throw rdsf::cli::UsageError("--min-height must be > 0 and below --max-height");
    if (!(o.voxel_size_m >= 0.01 && o.voxel_size_m <= 0.5)) throw rdsf::cli::UsageError("--voxel-size must be 0.01 to 0.5 m");
    if (!(o.ground.max_tilt_deg > 0 && o.ground.max_tilt_deg <= 60)) throw rdsf::cli::UsageError("--ground-max-tilt must be in (0, 60] degrees");
    if (o.svm.empty()) throw rdsf::cli::UsageError("--svm names no file");
    return rdsf::peers::run_pcl_people(o);
  });
}
