// rdsf-background: learns a background model of the room from a static camera's frames, for
// rdsf-detect --background (rdsf/segmentation/background_model.hpp, docs/candidates.md).
#include "cli/cli.hpp"
#include "detector/background_run.hpp"

const rdsf::cli::ProgramInfo kProgram{
    "rdsf-background", "--source SRC --out DIR [--frames N] [--quantile Q]",
    "Learns a background model of the room from the frames of a static camera: per pixel the room's far\n"
    "depth. rdsf-detect --background DIR then adds whatever stands in front of the room as candidates\n"
    "(people beside a wall or a cupboard that share its depth layer). A moving camera has no background."};

int main(int argc, char** argv) {
  return rdsf::cli::run(kProgram.name, [&] {
    namespace po = rdsf::cli::po;
    rdsf::BackgroundOptions o;
    po::options_description options(kProgram.name);
    options.add_options()
        ("source", po::value(&o.source)->required(),
         "frames of one static camera: a folder of NAME.depth.png, a list file, an .oni file or a ROS 1 .bag")
        ("out", po::value(&o.out)->required(), "the folder to write (background.depth.png and camera.yml)")
        ("frames", po::value(&o.frames)->default_value(o.frames),
         "learn from at most this many frames, spread evenly over the source (its first ones when its length is "
         "not known); each is kept in memory (640x480: 0.6 MB)")
        ("quantile", po::value(&o.quantile)->default_value(o.quantile, rdsf::cli::shortest_text(o.quantile)),
         "per pixel the room's depth is this quantile of its readings in the frames, near to far (frames without "
         "a reading there left out): anything nearer in fewer than 1 - this of them (people passing) is left out")
        ("force", po::bool_switch(&o.force), "replace a background already in --out");
    rdsf::cli::CameraOptions camera(options, o.camera, &o.frame_options);
    po::variables_map values;
    if (!rdsf::cli::parse(argc, argv, kProgram, options, values, camera)) return 0;
    if (o.frames < 1) throw rdsf::cli::UsageError("--frames must be at least 1");
    if (!(o.quantile >= 0.0 && o.quantile <= 1.0)) throw rdsf::cli::UsageError("--quantile must be in [0, 1]");
    return rdsf::run_background(o);
  });
}
