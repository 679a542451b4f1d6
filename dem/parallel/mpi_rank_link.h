#pragma once
// RankLink over MPI (the C API of Open MPI): the engine's messages between neighbouring ranks
// and its reductions, with the time and bytes they took.
#include "dem/engine/rank_link.h"

#include <mpi.h>

#include <cstdint>
#include <vector>

namespace wear::dem {

/// What a rank's messages cost since the last reset: the time inside MPI (which includes
/// waiting for a neighbour that is still computing: the load imbalance shows here) and what
/// it sent.
struct RankTraffic {
  double seconds = 0;         ///< [s] wall time in MPI calls
  double bytes_sent = 0;      ///< [B] payload sent to neighbours and in reductions
  std::uint64_t messages = 0; ///< [-] MPI calls that sent something
};

/// The ranks of one communicator as a line (rank r's neighbours are r - 1 and r + 1) or, for a
/// periodic sector or slab, a ring (the last rank's neighbour above is rank 0).
class MpiRankLink final : public RankLink {
public:
  explicit MpiRankLink(MPI_Comm comm, bool ring = false);
  int rank() const override { return rank_; }
  int n_ranks() const override { return n_ranks_; }
  bool ring() const override { return ring_; }
  /// MPI_Sendrecv of the count, then of the values.
  void shift(int direction, const std::vector<double>& send, std::vector<double>& receive) override;
  void max_over_ranks(double* values, std::size_t n) override;
  /// Gathered to rank 0, added there in rank order, broadcast.
  void sum_in_rank_order(double* values, std::size_t n) override;
  /// MPI_Allgather of the counts, then MPI_Allgatherv.
  void gather_in_rank_order(const std::vector<double>& mine, std::vector<double>& all) override;
  /// MPI_Gather of the counts, then MPI_Gatherv (the whole bed must fit MPI's int counts).
  void gather_to_first(const std::vector<double>& mine, std::vector<double>& all,
                       std::vector<std::size_t>& counts) override;

  const RankTraffic& traffic() const { return traffic_; }
  void reset_traffic() { traffic_ = {}; }

private:
  MPI_Comm comm_;
  int rank_ = 0, n_ranks_ = 1;
  bool ring_ = false;
  std::vector<double> gathered_; ///< rank 0's copy of every rank's values
  std::vector<int> counts_, offsets_;
  RankTraffic traffic_;
};

/// Adds vectors over the ranks of `comm` in rank order (gather to rank 0, add 0, 1, 2, ...,
/// broadcast): every rank gets the same bits whatever the timing.
void sum_in_rank_order(MPI_Comm comm, std::vector<double>& values);

} // namespace wear::dem
