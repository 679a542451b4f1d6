// Per-rank figures of `wearsim bench dem` under mpirun.
//
// A rank's loop time splits into the time inside MPI (the link's traffic counters: messages to
// the neighbours, reductions, and the wait for a neighbour still computing) and the time
// outside, its own computation. The load imbalance is max / mean of the computation over the
// ranks (and, for reference, of the particle counts): the slowest rank sets the pace, the
// others wait inside MPI. Bytes and messages per step are what the rank sent (payload).
#include "coupling/app/bench_ranks.h"

#include "coupling/output/text_format.h"

#include <algorithm>
#include <ostream>

namespace wear::coupling {

std::vector<RankRow> gather_rank_rows(const dem::System& s, dem::MpiRankLink& link,
                                      double loop_seconds) {
  const dem::RankTraffic& t = link.traffic();
  const std::vector<double> mine{
      double(s.particles.n_real), double(s.n_ghosts()), loop_seconds, t.seconds, t.bytes_sent,
      double(t.messages)};
  std::vector<double> all;
  link.gather_in_rank_order(mine, all);
  std::vector<RankRow> rows;
  for (std::size_t k = 0; k + 6 <= all.size(); k += 6)
    rows.push_back({all[k], all[k + 1], all[k + 2], all[k + 3], all[k + 4], all[k + 5]});
  return rows;
}

double compute_imbalance(const std::vector<RankRow>& rows) {
  double largest = 0, sum = 0;
  for (const RankRow& r : rows) {
    const double compute = r.loop_seconds - r.comm_seconds;
    largest = std::max(largest, compute);
    sum += compute;
  }
  return sum > 0 ? largest * double(rows.size()) / sum : 1;
}

void print_rank_table(const std::vector<RankRow>& rows, std::uint64_t steps, std::ostream& out) {
  out << "  rank  particles  ghosts  particle-steps/s  in MPI  kB sent/step  messages/step\n";
  double n_max = 0, n_sum = 0;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const RankRow& w = rows[r];
    out << format("  %4zu  %9.0f  %6.0f  %16.4e  %5.1f %%  %12.2f  %13.1f\n", r, w.n_particles,
                  w.n_ghosts, w.n_particles * double(steps) / std::max(1e-9, w.loop_seconds),
                  100 * w.comm_seconds / std::max(1e-9, w.loop_seconds),
                  w.bytes_sent / double(std::max<std::uint64_t>(1, steps)) / 1e3,
                  w.messages / double(std::max<std::uint64_t>(1, steps)));
    n_max = std::max(n_max, w.n_particles);
    n_sum += w.n_particles;
  }
  out << format("  load imbalance (largest / mean): computation %.3f, particles %.3f\n",
                compute_imbalance(rows), n_sum > 0 ? n_max * double(rows.size()) / n_sum : 1.0);
}

} // namespace wear::coupling
