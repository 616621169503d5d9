// rdsf-record: records depth (and registered colour) from a live OpenNI2 device into an .oni file.
#include "cli/cli.hpp"
#include "recorder/record_run.hpp"

const rdsf::cli::ProgramInfo kProgram{
    "rdsf-record", "--out FILE.oni [--device URI] [--frames N] [--colour] [options]",
    "Records a live OpenNI2 device (a Kinect, or the virtual sensor rdsf-png://FOLDER) with OpenNI2's own\n"
    "recorder, lossless. Ctrl-C stops and keeps a playable file. Read it back with --source FILE.oni."};

int main(int argc, char** argv) {
  return rdsf::cli::run(kProgram.name, [&] {
    namespace po = rdsf::cli::po;
    rdsf::recorder::RecordOptions o;
    bool no_depth = false;
    po::options_description options(kProgram.name);
    options.add_options()
        ("out", po::value(&o.out)->required(), "the recording to write (FILE.oni)")
        ("device", po::value(&o.device)->default_value(o.device),
         "'openni' for the first attached device, a device URI, or rdsf-png://FOLDER (virtual sensor)")
        ("frames", po::value(&o.frames)->default_value(o.frames),
         "stop after N frames of every stream; 0 records until Ctrl-C")
        ("colour", po::bool_switch(&o.colour), "record the colour stream too, registered to depth")
        ("no-depth", po::bool_switch(&no_depth), "leave depth out (with --colour: colour-only test files)")
        ("timeout-ms", po::value(&o.timeout_ms)->default_value(o.timeout_ms),
         "longest wait for a frame before the device counts as stopped")
        ("force", po::bool_switch(&o.force), "replace an existing --out file");
    po::variables_map values;
    if (!rdsf::cli::parse(argc, argv, kProgram, options, values)) return 0;
    o.depth = !no_depth;
    rdsf::recorder::check_options(o);
    return rdsf::recorder::run_record(o);
  });
}
