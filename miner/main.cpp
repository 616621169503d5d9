// rdsf-mine: mines negatives (every candidate of people-free frames, or a model's false positives) into a
// sample set; --merge joins sample sets (e.g. the shards of a job array).
#include "cli/cli.hpp"
#include "cli/common_options.hpp"
#include "miner/mine_run.hpp"

const rdsf::cli::ProgramInfo kProgram{
    "rdsf-mine",
    "--source SRC... --out SET [--model M --min-score T] [--stride N] [--max N] [--shard i/n]\n"
    "       rdsf-mine --merge SET1 SET2 ... --out SET",
    "Runs the frame analyser on people-free frames and appends every candidate to the sample set SET as a\n"
    "negative (label 0, origin miner); with --model only the candidates the model scores at or above\n"
    "--min-score (its false positives). Exact duplicates are skipped, so a run killed midway continues\n"
    "when started again with the same options. --merge joins sample sets, e.g. shard outputs."};

int main(int argc, char** argv) {
  return rdsf::cli::run(kProgram.name, [&] {
    namespace po = rdsf::cli::po;
    rdsf::MineOptions o;
    po::options_description options(kProgram.name);
    options.add_options()
        ("source", po::value(&o.mine.sources)->multitoken(),
         "people-free frames, one or more: folders of NAME.depth.png, list files, PNGs, .oni files, devices")
        ("out", po::value(&o.out)->required(), "the sample set folder to append to (created when absent)");
    rdsf::cli::add_model_option(options, o.model, "hard-negative mode: keep only candidates this model scores >= --min-score");
    rdsf::cli::add_models_dir_option(options, o.models_dir);
    options.add_options()
        ("min-score", po::value(&o.min_score)->default_value(o.min_score), "hard-negative mode: score threshold")
        ("stride", po::value(&o.mine.stride)->default_value(o.mine.stride), "use every N-th frame of each source")
        ("max", po::value(&o.mine.max_negatives)->default_value(0),
         "stop once the set holds N negatives (0: no limit; a resumed run stops at the same total)")
        ("max-frames", po::value(&o.mine.max_frames)->default_value(0), "stop after N frames (0: no limit)")
        ("shard", po::value(&o.shard)->default_value(o.shard),
         "mine slice i of n (1-based): of the strided frames k = index / stride, those with k % n == i - 1; "
         "e.g. --shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT");
    rdsf::cli::add_threads_option(options, o.mine.threads, "threads analysing frames, this one among them");
    options.add_options()
        ("sync-every", po::value(&o.mine.sync_every_frames)->default_value(o.mine.sync_every_frames),
         "flush to disk once per N frames (group commit; a kill or power cut loses at most the frames since "
         "the last flush, which a rerun mines again; 1: after every frame)")
        ("depth-only", po::bool_switch(&o.mine.depth_only),
         "do not read the frames' colour: crops without colour, faster (decoding colour PNGs dominates)")
        ("merge", po::value(&o.merge)->multitoken(),
         "merge mode: append these sample sets to --out (feature specs must match; duplicates skipped)");
    rdsf::cli::CameraOptions camera(options, o.mine.camera);
    options.add(rdsf::cli::analyser_options(o.mine.analyser));
    po::variables_map values;
    if (!rdsf::cli::parse(argc, argv, kProgram, options, values, camera)) return 0;
    o.min_score_given = !values["min-score"].defaulted();
    o.given = rdsf::cli::given_analyser_options(values);
    return o.merge.empty() ? rdsf::run_mine(o) : rdsf::run_merge(o);
  });
}
