// rdsf-train: turns sample sets into a versioned model file (models/NAME/vN.yml), inspects model files,
// exports samples in the thesis's text format. Under mpirun (built with MPI) every rank trains on its share
// of the rows (docs/scaling.md).
#include <iostream>
#include <memory>

#include "cli/cli.hpp"
#include "rdsf/version.hpp"
#include "trainer/ranks.hpp"
#include "trainer/train_options.hpp"
#include "trainer/train_run.hpp"
#if RDSF_WITH_MPI
#include "trainer/mpi_shards.hpp"
#endif

const rdsf::cli::ProgramInfo kProgram{
    "rdsf-train", "--recipe NAME | --pos SET --neg SET --name NAME | --inspect MODEL [options]",
    "Trains a person classifier on RDSF features of sample sets and saves it as MODELS/NAME/vN.yml, N one\n"
    "higher than the newest (never overwriting). Native Real AdaBoost by default (about 0.1-0.2 s per round\n"
    "at 28,000 samples on 2 cores), OpenCV's boosting with --backend opencv. Progress per round on stderr.\n"
    "Data-parallel under mpirun -np N when built with MPI (docs/scaling.md)."};

int main(int argc, char** argv) {
#if RDSF_WITH_MPI
  const rdsf::MpiSession mpi(argc, argv);
  const std::unique_ptr<rdsf::RowShards> shards =
      mpi.active() ? std::unique_ptr<rdsf::RowShards>(new rdsf::MpiShards) : std::make_unique<rdsf::RowShards>();
#else
  const auto shards = std::make_unique<rdsf::RowShards>();
#endif
  const bool ranks = shards->distributed();
  const std::string name = ranks ? kProgram.name + " (rank " + std::to_string(shards->rank()) + " of " +
                                       std::to_string(shards->size()) + ")"
                                 : kProgram.name;
  bool agreed = false;  // a failure every rank knows of (reported by rank 0)
  int code = 1;
  try {
    code = rdsf::cli::run(name, [&] {
      const rdsf::QuietCerr quiet(shards->rank() != 0);  // progress from rank 0 only; errors from every rank
      namespace po = rdsf::cli::po;
      rdsf::TrainOptions o;
      po::options_description options = rdsf::train_options(o);
      po::variables_map values;
      if (!rdsf::cli::parse(argc, argv, kProgram, options, values)) return 0;
      o.feature_spec_given = !values["feature-spec"].defaulted();  // else the sets' spec
      rdsf::check_options(o, ranks);
      if (!o.inspect.empty()) return rdsf::run_inspect(o, std::cout);
      if (!o.export_text.empty()) return rdsf::run_export_text(o);
      try {
        return rdsf::run_train(o, *shards);
      } catch (const rdsf::AgreedError&) {
        agreed = true;
        throw;
      }
    });
  } catch (const rdsf::QuietExit& e) {
    code = e.code;
    agreed = true;
  }
  // Every rank knows of the failure: the others wait until rank 0 has reported it (mpirun ends the job as
  // soon as one rank exits non-zero).
  if (ranks && agreed) shards->gather_text("");
#if RDSF_WITH_MPI
  if (ranks && code == 0 && shards->rank() == 0) {
    std::cerr << kProgram.name << ": " << shards->size() << " ranks, rank 0: "
              << static_cast<const rdsf::MpiShards&>(*shards).traffic() << "\n";
  }
  // A failure on this rank alone: the others may wait for it in a collective call, so the job ends here.
  if (ranks && code != 0 && !agreed) mpi.abort(code);
#endif
  return code;
}
