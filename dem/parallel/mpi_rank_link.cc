// Messages of a DEM bed decomposed over MPI ranks (RankLink, rank_link.h).
//
// A shift sends a buffer of doubles to the neighbour above (or below) and receives the one the
// neighbour below (or above) sent the same way: two MPI_Sendrecv, the count first, then the
// values, so that a receiver sizes its buffer before the values arrive. On a line the first
// and last ranks talk to MPI_PROC_NULL on their open side (nothing sent, nothing received); on
// a ring (a periodic bed) they are each other's neighbours across the seam.
//
// Sums over ranks are taken in rank order, v_0 + v_1 + v_2 + ..., on rank 0 and broadcast: an
// MPI_Allreduce may add in an order that depends on the implementation and the timing, and
// floating-point addition is not associative, so every rank and every repetition of a run
// gets the same bits only this way. The gathers for evaluations (gather_in_rank_order) follow
// the same rule. Every call adds its wall time and the bytes it sent to the traffic counters
// (`wearsim bench dem` under mpirun prints them). Assumes the buffers hold doubles and every count
// fits an int (MPI's counts).
#include "dem/parallel/mpi_rank_link.h"

#include "dem/engine/reused_buffer.h"

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace wear::dem {

MpiRankLink::MpiRankLink(MPI_Comm comm, bool ring) : comm_(comm), ring_(ring) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &n_ranks_);
}

void MpiRankLink::shift(int direction, const std::vector<double>& send,
                        std::vector<double>& receive) {
  const double t0 = MPI_Wtime();
  const int up = rank_ + 1 < n_ranks_ ? rank_ + 1 : ring_ ? 0 : MPI_PROC_NULL;
  const int down = rank_ > 0 ? rank_ - 1 : ring_ ? n_ranks_ - 1 : MPI_PROC_NULL;
  const int to = direction > 0 ? up : down, from = direction > 0 ? down : up;
  const int tag = direction > 0 ? 1 : 2;
  std::uint64_t n_send = send.size(), n_receive = 0;
  MPI_Sendrecv(&n_send, 1, MPI_UINT64_T, to, tag, &n_receive, 1, MPI_UINT64_T, from, tag, comm_,
               MPI_STATUS_IGNORE);
  resize_reusing(receive, std::size_t(n_receive));
  MPI_Sendrecv(send.data(), int(n_send), MPI_DOUBLE, to, tag + 2, receive.data(), int(n_receive),
               MPI_DOUBLE, from, tag + 2, comm_, MPI_STATUS_IGNORE);
  if (to != MPI_PROC_NULL) {
    traffic_.bytes_sent += double(sizeof(std::uint64_t) + n_send * sizeof(double));
    traffic_.messages += 2;
  }
  traffic_.seconds += MPI_Wtime() - t0;
}

void MpiRankLink::max_over_ranks(double* values, std::size_t n) {
  const double t0 = MPI_Wtime();
  MPI_Allreduce(MPI_IN_PLACE, values, int(n), MPI_DOUBLE, MPI_MAX, comm_);
  traffic_.bytes_sent += double(n * sizeof(double));
  traffic_.messages += 1;
  traffic_.seconds += MPI_Wtime() - t0;
}

void MpiRankLink::sum_in_rank_order(double* values, std::size_t n) {
  const double t0 = MPI_Wtime();
  if (rank_ == 0)
    resize_reusing(gathered_, n * std::size_t(n_ranks_));
  MPI_Gather(values, int(n), MPI_DOUBLE, gathered_.data(), int(n), MPI_DOUBLE, 0, comm_);
  if (rank_ == 0)
    for (int r = 1; r < n_ranks_; ++r)
      for (std::size_t k = 0; k < n; ++k)
        values[k] += gathered_[std::size_t(r) * n + k];
  MPI_Bcast(values, int(n), MPI_DOUBLE, 0, comm_);
  traffic_.bytes_sent += double(n * sizeof(double));
  traffic_.messages += 2;
  traffic_.seconds += MPI_Wtime() - t0;
}

void MpiRankLink::gather_in_rank_order(const std::vector<double>& mine, std::vector<double>& all) {
  const double t0 = MPI_Wtime();
  counts_.resize(std::size_t(n_ranks_));
  offsets_.resize(std::size_t(n_ranks_));
  const int n = int(mine.size());
  MPI_Allgather(&n, 1, MPI_INT, counts_.data(), 1, MPI_INT, comm_);
  std::size_t total = 0;
  for (std::size_t r = 0; r < counts_.size(); ++r) {
    offsets_[r] = int(total);
    total += std::size_t(counts_[r]);
  }
  all.resize(total);
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts_.data(), offsets_.data(),
                 MPI_DOUBLE, comm_);
  traffic_.bytes_sent += double(sizeof(int) + mine.size() * sizeof(double));
  traffic_.messages += 2;
  traffic_.seconds += MPI_Wtime() - t0;
}

void MpiRankLink::gather_to_first(const std::vector<double>& mine, std::vector<double>& all,
                                  std::vector<std::size_t>& counts) {
  const double t0 = MPI_Wtime();
  if (mine.size() > std::size_t(std::numeric_limits<int>::max()))
    throw std::runtime_error("MpiRankLink: rank " + std::to_string(rank_) + " would send " +
                             std::to_string(mine.size()) + " values at once (MPI counts are int)");
  const int n = int(mine.size());
  counts_.resize(std::size_t(n_ranks_));
  offsets_.resize(std::size_t(n_ranks_));
  MPI_Gather(&n, 1, MPI_INT, counts_.data(), 1, MPI_INT, 0, comm_);
  all.clear();
  counts.clear();
  if (rank_ == 0) {
    std::size_t total = 0;
    for (std::size_t r = 0; r < counts_.size(); ++r) {
      offsets_[r] = int(total);
      total += std::size_t(counts_[r]);
      counts.push_back(std::size_t(counts_[r]));
    }
    if (total > std::size_t(std::numeric_limits<int>::max()))
      throw std::runtime_error("MpiRankLink: the ranks' states hold " + std::to_string(total) +
                               " values in all, beyond MPI's int offsets");
    all.resize(total);
  }
  MPI_Gatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts_.data(), offsets_.data(), MPI_DOUBLE,
              0, comm_);
  traffic_.bytes_sent += double(sizeof(int) + mine.size() * sizeof(double));
  traffic_.messages += 2;
  traffic_.seconds += MPI_Wtime() - t0;
}

void sum_in_rank_order(MPI_Comm comm, std::vector<double>& values) {
  MpiRankLink(comm).sum_in_rank_order(values.data(), values.size());
}

} // namespace wear::dem
