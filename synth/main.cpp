// rdsf-synth: renders a synthetic Kinect v1 recording (depth, optional colour, person boxes).
#include <string>

#include "cli/cli.hpp"
#include "synth/synth_run.hpp"

int main(int argc, char** argv) {
  return rdsf::cli::run("rdsf-synth", [&] {
    namespace po = rdsf::cli::po;
    rdsf::SynthOptions o;
    for (int i = 0; i < argc; ++i) o.command_line += (i ? " " : "") + std::string(argv[i]);
    po::options_description options("rdsf-synth");
    // clang-format off
    options.add_options()
        ("out", po::value(&o.out_dir)->required(),
         "folder for NNNNNN.depth.png, NNNNNN.rgb.png, boxes.csv, synth.yml")
        ("frames", po::value(&o.params.frames)->default_value(o.params.frames), "number of frames")
        ("people", po::value(&o.people)->default_value(o.people), "people in each clip's room: MIN..MAX")
        ("seed", po::value(&o.params.seed)->default_value(o.params.seed), "random seed (same seed, same bytes)")
        ("empty", po::bool_switch(&o.params.empty), "render the same rooms without people (negatives)")
        ("size", po::value(&o.size)->default_value(o.size), "image size WIDTHxHEIGHT, multiples of 8")
        ("rgb", po::bool_switch(&o.params.rgb), "also write the registered colour image NNNNNN.rgb.png")
        ("clip-frames", po::value(&o.params.clip_frames)->default_value(o.params.clip_frames),
         "frames per clip: each clip has a new room, camera pose and people")
        ("force", po::bool_switch(&o.force), "replace the frames of an earlier set in --out");
    // clang-format on
    po::variables_map values;
    const rdsf::cli::ProgramInfo info{
        "rdsf-synth", "--out DIR [--frames N] [--people MIN..MAX] [--seed S] [--empty] [--size WxH] [--rgb]",
        "Renders a synthetic Kinect v1 recording: indoor rooms with furniture and walking, standing people,\n"
        "seen through a model of the sensor (range 0.5-8 m, noise growing with distance squared, shadows\n"
        "and holes). Writes the frame-source layout (readable by every --source option) and boxes.csv with\n"
        "the tight box of each person's visible pixels and its track id. Same options, same bytes."};
    if (!rdsf::cli::parse(argc, argv, info, options, values)) return 0;
    return rdsf::run_synth(o);
  });
}
