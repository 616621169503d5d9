#pragma once
// rdsf-train over several processes (issue 37): what every rank must agree on, and how a failure on one
// rank becomes one line on rank 0 and a non-zero exit on all. MPI-free: the ranks talk through
// rdsf::RowShards (one process: the checks pass at once).
#include <functional>
#include <streambuf>
#include <string>

#include "rdsf/classifier/row_shards.hpp"
#include "rdsf/core/error.hpp"

namespace rdsf {

/// Thrown on the ranks other than 0 when a failure was agreed (rank 0 reports it): main exits with
/// `code` without another message. Not an std::exception, so cli::run lets it through.
struct QuietExit {
  int code = 1;
};

/// The failure every rank learnt of (thrown on rank 0, which reports it): no MPI_Abort is needed.
struct AgreedError : Error {
  using Error::Error;
};

/// Runs `step` on every rank; when it throws on any rank, every rank learns it: rank 0 throws AgreedError("rank R
/// of N: <what>: <message>") naming the first rank that failed, the others QuietExit. One process: `step`
/// as it is.
void on_every_rank(const RowShards& shards, const std::string& what, const std::function<void()>& step);

/// Every rank's `text` (options, feature spec, sets) must equal rank 0's: otherwise rank 0 throws
/// AgreedError("rank R of N has other WHAT than rank 0: 'line' vs 'line'") with the first line that differs.
void check_ranks_agree(const RowShards& shards, const std::string& what, const std::string& text);

/// While alive, std::cerr writes nothing (rank > 0 keeps the progress to rank 0); restored on destruction,
/// also when an exception leaves, so an error is still printed.
class QuietCerr {
 public:
  explicit QuietCerr(bool quiet);
  ~QuietCerr();
  QuietCerr(const QuietCerr&) = delete;
  QuietCerr& operator=(const QuietCerr&) = delete;

 private:
  struct Null : std::streambuf {
    int overflow(int c) override { return c == EOF ? 0 : c; }
  } null_;
  std::streambuf* saved_ = nullptr;
};

}  // namespace rdsf
