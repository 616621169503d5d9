#pragma once
// rdsf::RowShards over MPI (OpenMPI; built only with RDSF_WITH_MPI, linked only into rdsf-train).
//   sum: a reduce-scatter in rank order and an allgather, as LightGBM's data-parallel learner exchanges
//     its histograms (Network::ReduceScatter, then every rank has every sum): the values are cut into one
//     block per rank; rank r receives block r of every rank (MPI_Alltoallv), adds them as
//     (((b_0 + b_1) + b_2) + ...) and every rank receives every summed block (MPI_Allgatherv). Each value
//     crosses the wire about 2 (N - 1) / N times, like a ring allreduce, and the order of the additions is
//     fixed (MPI_Allreduce's is the library's choice). Short arrays (fewer values than 64 per rank) are
//     gathered whole and added in rank order on every rank.
//   sum_own_block: the reduce-scatter alone, in whole units (a feature's histogram): the best split is then
//     found per block and only the winners are exchanged (LightGBM's best-split exchange), about half the
//     bytes of sum().
//   max: MPI_Allreduce (MPI_MAX; exact in any order). gather: MPI_Allgatherv.
// Time and bytes in these calls are counted for the report at the end (docs/scaling.md).
#include <cstdint>
#include <string>

#include "rdsf/classifier/row_shards.hpp"

namespace rdsf {

/// MPI_Init when this process was started by mpirun (OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_RANK set),
/// MPI_Finalize at the end; otherwise nothing (one process, no MPI at all).
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  bool active() const { return active_; }
  /// Ends every rank of the job with `code` (MPI_Abort): for a failure the other ranks cannot learn of.
  [[noreturn]] void abort(int code) const;

 private:
  bool active_ = false;
};

class MpiShards : public RowShards {
 public:
  MpiShards();  ///< MPI_COMM_WORLD; needs an active MpiSession
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void sum(double* values, std::size_t count) const override;
  std::pair<std::size_t, std::size_t> sum_own_block(double* values, std::size_t units,
                                                     std::size_t unit_size) const override;
  void max(double* values, std::size_t count) const override;
  std::vector<double> gather(const std::vector<double>& local) const override;
  std::vector<std::string> gather_text(const std::string& local) const override;
  /// "C calls, B MB sent by this rank, S s in them".
  std::string traffic() const;
  double seconds() const { return seconds_; }

 private:
  /// Rank r receives block r ([begin[r], begin[r + 1]) of `values`) of every rank and stores their sum, in
  /// rank order, over its own block of `values`.
  void reduce_scatter(double* values, const std::vector<int>& begin) const;
  int rank_ = 0, size_ = 1;
  mutable double seconds_ = 0.0;
  mutable std::uint64_t bytes_ = 0, calls_ = 0;
};

}  // namespace rdsf
