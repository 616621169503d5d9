// rdsf-samples: describes a sample set, imports or exports the thesis's text format ("label f1 ... f8128").
#include "cli/cli.hpp"
#include "miner/samples_run.hpp"

const rdsf::cli::ProgramInfo kProgram{
    "rdsf-samples", "[--set] SET [--import FILE | --export FILE [--force] | --check | --repair]",
    "Without --import or --export, describes the sample set SET (counts, feature spec, camera). --import\n"
    "reads the thesis's text format (one sample a line: label 1 or 0, then 8128 feature values in [0, 1]);\n"
    "imported samples have no crop, their vectors are stored. --export writes it, features computed from\n"
    "the crops."};

int main(int argc, char** argv) {
  return rdsf::cli::run(kProgram.name, [&] {
    namespace po = rdsf::cli::po;
    rdsf::SamplesOptions o;
    po::options_description options(kProgram.name);
    options.add_options()
        ("set", po::value(&o.set)->required(), "the sample set folder")
        ("import", po::value(&o.import_file),
         "append the samples of this thesis text file (label f1 ... f8128 a line) to the set, creating it when "
         "absent; every line is checked first")
        ("export", po::value(&o.export_file), "write the set's samples to this thesis text file")
        ("force", po::bool_switch(&o.force), "replace an existing --export file")
        ("check", po::bool_switch(&o.check),
         "list every problem of the set (torn rows, duplicate ids, missing, truncated or replaced crops, crops "
         "without a row); exit 1 when there is one")
        ("repair", po::bool_switch(&o.repair),
         "repair what --check finds and can be repaired, after copying samples.tsv to samples.tsv.bak-TIME; "
         "prints each change");
    po::variables_map values;
    po::positional_options_description positional;  // "rdsf-samples --check SET" as well as "--set SET"
    positional.add("set", 1);
    if (!rdsf::cli::parse(argc, argv, kProgram, options, values, &positional)) return 0;
    return rdsf::run_samples(o);
  });
}
