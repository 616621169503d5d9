// rdsf-synth: renders a synthetic Kinect v1 recording (depth, optional colour, person boxes).
#include <string>

#include "cli/cli.hpp"
#include "rdsf/synth/synth_params.hpp"
#include "synth/synth_run.hpp"

const rdsf::cli::ProgramInfo kProgram{
    "rdsf-synth", "--out DIR [--frames N] [--people MIN..MAX] [--seed S] [--empty] [--size WxH] [--rgb]",
    "Renders a synthetic Kinect v1 recording: indoor rooms with furniture and walking, standing people,\n"
    "seen through a model of the sensor (range 0.5-8 m, noise growing with distance squared, shadows\n"
    "and holes). Writes the frame-source layout (readable by every --source option) and boxes.csv with\n"
    "the tight box of each person's visible pixels and its track id. Same options, same bytes.\n"
    "Rooms, people and captures vary as in a lab (see docs/synthetic.md); each variety can be turned off."};

int main(int argc, char** argv) {
  return rdsf::cli::run(kProgram.name, [&] {
    namespace po = rdsf::cli::po;
    rdsf::SynthOptions o;
    for (int i = 0; i < argc; ++i) o.command_line += (i ? " " : "") + std::string(argv[i]);
    // the rows of synth_parameters() from `first` to `last`; their values are set by run_synth
    const auto add_rows = [&o](po::options_description& group, const char* first, const char* last) {
      rdsf::cli::add_table_values(group, rdsf::rows_between(rdsf::synth::synth_parameters(), first, last), o.params,
                                  o.values);
    };
    po::options_description options(kProgram.name);
    options.add_options()("out", po::value(&o.out_dir)->required(),
                          "folder for NNNNNN.depth.png, NNNNNN.rgb.png, boxes.csv, synth.yml");
    add_rows(options, "frames", "people");
    // not a row: ParameterValue holds no unsigned 64-bit number
    options.add_options()("seed", po::value(&o.params.seed)->default_value(o.params.seed),
                          "random seed (same seed, same bytes)");
    add_rows(options, "empty", "clip-frames");
    options.add_options()("force", po::bool_switch(&o.force), "replace the frames of an earlier set in --out");
    po::options_description variety("variety of rooms, people and captures (all on by default)");
    add_rows(variety, "camera-height", "coherent-holes");
    variety.add_options()("classic", po::bool_switch(&o.classic),
                          "turn all of the variety above off: the generator before it (overrides these options)");
    options.add(variety);
    po::variables_map values;
    if (!rdsf::cli::parse(argc, argv, kProgram, options, values)) return 0;
    return rdsf::run_synth(o);
  });
}
