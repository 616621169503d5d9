#pragma once
// Data-parallel training (issue 37): the training rows split over N processes ("ranks", e.g. under
// `mpirun -np N rdsf-train`), each holding and binning only its share; what a round needs of the others is
// exchanged through this interface, so the library does not depend on MPI (rdsf-train implements it with
// MPI when built with it; see docs/scaling.md). The one-process RowShards below does nothing.
//
// Every rank knows every row's label, group and owner (small); only the feature rows are split. Sums are
// taken in rank order, (((v_0 + v_1) + v_2) + ...), the same bits on every rank, so every rank picks the
// same split; they are not the bits of one process's sums (a different order of the same additions), so
// a model trained on N ranks equals the one-process model up to the last bits of its responses unless a
// near tie breaks otherwise (docs/scaling.md states the largest difference measured).
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace rdsf {

class RowShards {
 public:
  virtual ~RowShards() = default;
  virtual int rank() const { return 0; }
  virtual int size() const { return 1; }
  bool distributed() const { return size() > 1; }
  /// values[k] <- the sum over ranks of their values[k], added in rank order: the same bits on every rank.
  virtual void sum(double* values, std::size_t count) const;
  /// The reduce-scatter half of sum(): `values` are `units` runs of `unit_size`; this rank's block of units
  /// [first, last) (contiguous blocks in rank order, every unit in one) becomes the sum over ranks, added in
  /// rank order (the same bits as sum()); the other values are left as they were. Returns {first, last}.
  /// One process: every unit, unchanged.
  virtual std::pair<std::size_t, std::size_t> sum_own_block(double* values, std::size_t units,
                                                             std::size_t unit_size) const;
  /// values[k] <- the largest of the ranks' values[k].
  virtual void max(double* values, std::size_t count) const;
  /// Every rank's `local` (lengths may differ), concatenated in rank order; the same on every rank.
  virtual std::vector<double> gather(const std::vector<double>& local) const;
  /// Every rank's text, by rank (for checks that the ranks agree).
  virtual std::vector<std::string> gather_text(const std::string& local) const;
};

/// The full vector of a quantity known per entry by the entry's owner: entry k (in order) belongs to rank
/// owner[k]; `local` holds this rank's entries in order. Every rank gets all entries in order.
std::vector<double> gather_in_order(const RowShards& shards, const std::vector<double>& local,
                                    const std::vector<int>& owner);

/// A rank's share of rows given by global index: local_of[i] is row i's index in this rank's matrix, or -1
/// when another rank holds it. Empty owner: every row is here (one process).
struct RowOwners {
  const RowShards* shards = nullptr;  ///< null: one process
  std::vector<int> owner;             ///< per global row: the rank holding it
  std::vector<long> local_of;         ///< per global row: its row in this rank's matrix, -1 elsewhere

  RowOwners() = default;
  RowOwners(const RowShards* s, std::vector<int> owners);
  bool distributed() const { return shards != nullptr && shards->distributed(); }
  /// Row i's index in this rank's matrix, or -1.
  long local(std::size_t i) const { return owner.empty() ? static_cast<long>(i) : local_of[i]; }
  /// The owners of the rows `index` lists, in that order (empty when one process).
  std::vector<int> owners_of(const std::vector<std::size_t>& index) const;
  /// The owners of rows `index` (as ints) of this, for a matrix holding only those rows.
  RowOwners subset(const std::vector<int>& index) const;
  /// Values computed here for the entries `index` lists that this rank holds (in order), made whole.
  std::vector<double> whole(const std::vector<double>& local, const std::vector<std::size_t>& index) const;
};

}  // namespace rdsf
