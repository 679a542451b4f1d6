#pragma once
// `wearsim bench dem` under mpirun: what each rank did in a timed loop, gathered to every rank.
#include "dem/engine/system.h"
#include "dem/parallel/mpi_rank_link.h"

#include <iosfwd>
#include <vector>

namespace wear::coupling {

/// One rank's share of a timed loop.
struct RankRow {
  double n_particles = 0; ///< [-] real particles at the end of the loop
  double n_ghosts = 0;    ///< [-] ghost slots (periodic images and the rank below's)
  double loop_seconds = 0;
  double comm_seconds = 0; ///< [s] inside MPI (messages, reductions, waiting for neighbours)
  double bytes_sent = 0;   ///< [B]
  double messages = 0;     ///< [-]
};

/// Every rank's row of the loop that just ran (`link`'s traffic since its last reset), in rank
/// order; every rank calls it together.
std::vector<RankRow> gather_rank_rows(const dem::System& s, dem::MpiRankLink& link,
                                      double loop_seconds);

/// The per-rank table of one loop of `steps` steps: particles, ghosts, particle-steps/s, share
/// of time in MPI, bytes and messages per step; then the load imbalance (largest over mean of
/// the particles and of the time outside MPI).
void print_rank_table(const std::vector<RankRow>& rows, std::uint64_t steps, std::ostream& out);

/// [-] Largest over mean of the ranks' time outside MPI (1: balanced).
double compute_imbalance(const std::vector<RankRow>& rows);

} // namespace wear::coupling
