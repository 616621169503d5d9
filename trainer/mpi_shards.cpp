#include "trainer/mpi_shards.hpp"

#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "rdsf/core/error.hpp"

namespace rdsf {
namespace {

using Clock = std::chrono::steady_clock;

bool launched_by_mpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    const char* value = std::getenv(name);
    if (value != nullptr && *value != '\0') return true;
  }
  return false;
}

void check(int code, const char* call) {
  if (code != MPI_SUCCESS) throw Error(std::string("MPI: ") + call + " failed (code " + std::to_string(code) + ")");
}

int as_int(std::size_t n) {
  if (n > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw Error("MPI: " + std::to_string(n) + " values in one call are more than MPI counts hold");
  }
  return static_cast<int>(n);
}

// Adds the time of one collective call to the counters.
struct Timed {
  Timed(double& seconds, std::uint64_t& calls) : seconds_(seconds), start_(Clock::now()) { ++calls; }
  ~Timed() { seconds_ += std::chrono::duration<double>(Clock::now() - start_).count(); }
  double& seconds_;
  Clock::time_point start_;
};

// Every rank's count of values (MPI_Allgather) and where each rank's values begin in the whole; returns
// the total.
std::size_t gathered_layout(int mine, int size, std::vector<int>& counts, std::vector<int>& begin) {
  counts.assign(static_cast<std::size_t>(size), 0);
  begin.assign(static_cast<std::size_t>(size), 0);
  check(MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "MPI_Allgather");
  std::size_t total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    begin[r] = as_int(total);
    total += static_cast<std::size_t>(counts[r]);
  }
  return total;
}

}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
  if (!launched_by_mpirun()) return;
  int provided = 0;
  check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  // A failure reaches us as an error code, not an abort inside MPI, so that it can be reported.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  active_ = true;
}

MpiSession::~MpiSession() {
  if (active_) MPI_Finalize();
}

void MpiSession::abort(int code) const {
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);
}

MpiShards::MpiShards() {
  check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
  check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
}


void MpiShards::reduce_scatter(double* values, const std::vector<int>& begin) const {
  const auto ranks = static_cast<std::size_t>(size_), mine = static_cast<std::size_t>(rank_);
  std::vector<int> length(ranks);
  for (std::size_t r = 0; r < ranks; ++r) length[r] = begin[r + 1] - begin[r];
  const int block = length[mine];
  std::vector<int> receive_length(ranks, block), receive_begin(ranks);
  for (std::size_t r = 0; r < ranks; ++r) receive_begin[r] = as_int(r * static_cast<std::size_t>(block));
  std::vector<double> blocks(ranks * static_cast<std::size_t>(block));
  check(MPI_Alltoallv(values, length.data(), begin.data(), MPI_DOUBLE, blocks.data(), receive_length.data(),
                      receive_begin.data(), MPI_DOUBLE, MPI_COMM_WORLD),
        "MPI_Alltoallv");
  double* out = values + begin[mine];
  for (std::size_t k = 0; k < static_cast<std::size_t>(block); ++k) {
    double s = blocks[k];
    for (std::size_t r = 1; r < ranks; ++r) s += blocks[r * static_cast<std::size_t>(block) + k];
    out[k] = s;
  }
  bytes_ += (static_cast<std::size_t>(begin[ranks]) - static_cast<std::size_t>(block)) * sizeof(double);
}

std::pair<std::size_t, std::size_t> MpiShards::sum_own_block(double* values, std::size_t units,
                                                              std::size_t unit_size) const {
  if (size_ <= 1) return {0, units};
  const Timed timed(seconds_, calls_);
  const auto ranks = static_cast<std::size_t>(size_), mine = static_cast<std::size_t>(rank_);
  std::vector<int> begin(ranks + 1);  // whole units per rank
  for (std::size_t r = 0; r <= ranks; ++r) begin[r] = as_int(units * r / ranks * unit_size);
  reduce_scatter(values, begin);
  return {units * mine / ranks, units * (mine + 1) / ranks};
}

void MpiShards::sum(double* values, std::size_t count) const {
  if (size_ <= 1 || count == 0) return;
  const Timed timed(seconds_, calls_);
  const auto ranks = static_cast<std::size_t>(size_);
  if (count < 64 * ranks) {  // short: gather whole, add in rank order
    std::vector<double> all(count * ranks);
    check(MPI_Allgather(values, as_int(count), MPI_DOUBLE, all.data(), as_int(count), MPI_DOUBLE, MPI_COMM_WORLD),
          "MPI_Allgather");
    bytes_ += count * sizeof(double) * (ranks - 1);
    for (std::size_t k = 0; k < count; ++k) {
      double s = all[k];
      for (std::size_t r = 1; r < ranks; ++r) s += all[r * count + k];
      values[k] = s;
    }
    return;
  }
  // Block r = values [begin[r], begin[r + 1]): summed by rank r, then sent to every rank.
  std::vector<int> begin(ranks + 1), length(ranks);
  for (std::size_t r = 0; r <= ranks; ++r) begin[r] = as_int(count * r / ranks);
  for (std::size_t r = 0; r < ranks; ++r) length[r] = begin[r + 1] - begin[r];
  reduce_scatter(values, begin);
  const auto mine = static_cast<std::size_t>(rank_);
  check(MPI_Allgatherv(MPI_IN_PLACE, length[mine], MPI_DOUBLE, values, length.data(), begin.data(), MPI_DOUBLE,
                       MPI_COMM_WORLD),
        "MPI_Allgatherv");
  bytes_ += (count - static_cast<std::size_t>(length[mine])) * sizeof(double);
}

void MpiShards::max(double* values, std::size_t count) const {
  if (size_ <= 1 || count == 0) return;
  const Timed timed(seconds_, calls_);
  check(MPI_Allreduce(MPI_IN_PLACE, values, as_int(count), MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
  bytes_ += count * sizeof(double);
}

std::vector<double> MpiShards::gather(const std::vector<double>& local) const {
  if (size_ <= 1) return local;
  const Timed timed(seconds_, calls_);
  const int mine = as_int(local.size());
  std::vector<int> counts, begin;
  const std::size_t total = gathered_layout(mine, size_, counts, begin);
  std::vector<double> all(total);
  check(MPI_Allgatherv(local.data(), mine, MPI_DOUBLE, all.data(), counts.data(), begin.data(), MPI_DOUBLE,
                       MPI_COMM_WORLD),
        "MPI_Allgatherv");
  bytes_ += local.size() * sizeof(double) * static_cast<std::size_t>(size_ - 1);
  return all;
}

std::vector<std::string> MpiShards::gather_text(const std::string& local) const {
  if (size_ <= 1) return {local};
  const int mine = as_int(local.size());
  std::vector<int> counts, begin;
  const std::size_t total = gathered_layout(mine, size_, counts, begin);
  std::string all(total, '\0');
  check(MPI_Allgatherv(local.data(), mine, MPI_CHAR, all.data(), counts.data(), begin.data(), MPI_CHAR, MPI_COMM_WORLD),
        "MPI_Allgatherv");
  std::vector<std::string> out;
  for (std::size_t r = 0; r < counts.size(); ++r) out.push_back(all.substr(static_cast<std::size_t>(begin[r]), static_cast<std::size_t>(counts[r])));
  return out;
}

std::string MpiShards::traffic() const {
  char text[128];
  std::snprintf(text, sizeof text, "%llu collective calls, %.1f MB sent by this rank, %.2f s in them",
                static_cast<unsigned long long>(calls_), static_cast<double>(bytes_) / 1e6, seconds_);
  return text;
}

}  // namespace rdsf
