#pragma once
// RankLink over MPI (the C API of Open MPI): the engine's messages between neighbouring ranks
// and its reductions, and the wear integrals of a wearing wall summed over the ranks.
#include "dem/engine/rank_link.h"
#include "dem/engine/system.h"

#include <mpi.h>

#include <vector>

namespace wear::dem {

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

private:
  MPI_Comm comm_;
  int rank_ = 0, n_ranks_ = 1;
  bool ring_ = false;
  std::vector<double> gathered_; ///< rank 0's copy of every rank's values
};

/// Adds vectors over the ranks of `comm` in rank order (gather to rank 0, add 0, 1, 2, ...,
/// broadcast): every rank gets the same bits whatever the timing.
void sum_in_rank_order(MPI_Comm comm, std::vector<double>& values);

/// The window integrals of a wearing wall over every rank: each rank's System::wear_integrals,
/// added field by field in rank order (sum_in_rank_order), the same on every rank.
WearIntegrals wear_integrals_over_ranks(const System& system, int wall, RankLink& link);

} // namespace wear::dem
