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
// gets the same bits only this way. Assumes the buffers hold doubles and every count fits an
// int (MPI's counts).
#include "dem/parallel/mpi_rank_link.h"

#include "dem/engine/reused_buffer.h"

#include <cstdint>
#include <stdexcept>

namespace wear::dem {

MpiRankLink::MpiRankLink(MPI_Comm comm, bool ring) : comm_(comm), ring_(ring) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &n_ranks_);
}

void MpiRankLink::shift(int direction, const std::vector<double>& send,
                        std::vector<double>& receive) {
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
}

void MpiRankLink::max_over_ranks(double* values, std::size_t n) {
  MPI_Allreduce(MPI_IN_PLACE, values, int(n), MPI_DOUBLE, MPI_MAX, comm_);
}

void MpiRankLink::sum_in_rank_order(double* values, std::size_t n) {
  if (rank_ == 0)
    resize_reusing(gathered_, n * std::size_t(n_ranks_));
  MPI_Gather(values, int(n), MPI_DOUBLE, gathered_.data(), int(n), MPI_DOUBLE, 0, comm_);
  if (rank_ == 0)
    for (int r = 1; r < n_ranks_; ++r)
      for (std::size_t k = 0; k < n; ++k)
        values[k] += gathered_[std::size_t(r) * n + k];
  MPI_Bcast(values, int(n), MPI_DOUBLE, 0, comm_);
}

void sum_in_rank_order(MPI_Comm comm, std::vector<double>& values) {
  MpiRankLink(comm).sum_in_rank_order(values.data(), values.size());
}

WearIntegrals wear_integrals_over_ranks(const System& system, int wall, RankLink& link) {
  WearIntegrals w = system.wear_integrals(wall);
  const std::size_t nf = w.archard.size();
  // Flattened in WearIntegrals' order, then the totals.
  std::vector<double> v;
  v.reserve(n_wear_values * nf + 12);
  for (std::size_t f = 0; f < nf; ++f)
    v.insert(v.end(), {w.impulse[f].x, w.impulse[f].y, w.impulse[f].z, w.normal_impulse[f],
                       w.archard[f], w.sliding_work[f], w.contact_steps[f], w.normal_moment[f].x,
                       w.normal_moment[f].y, w.normal_moment[f].z, w.impulse_moment[f].x,
                       w.impulse_moment[f].y, w.impulse_moment[f].z});
  v.insert(v.end(), {w.total_archard, w.total_normal_impulse, w.total_sliding_work,
                     w.total_impulse.x, w.total_impulse.y, w.total_impulse.z,
                     w.total_normal_moment.x, w.total_normal_moment.y, w.total_normal_moment.z,
                     w.total_impulse_moment.x, w.total_impulse_moment.y, w.total_impulse_moment.z});
  link.sum_in_rank_order(v.data(), v.size());
  for (std::size_t f = 0; f < nf; ++f) {
    const double* a = &v[n_wear_values * f];
    w.impulse[f] = {a[0], a[1], a[2]};
    w.normal_impulse[f] = a[3];
    w.archard[f] = a[4];
    w.sliding_work[f] = a[5];
    w.contact_steps[f] = a[6];
    w.normal_moment[f] = {a[7], a[8], a[9]};
    w.impulse_moment[f] = {a[10], a[11], a[12]};
  }
  const double* t = &v[n_wear_values * nf];
  w.total_archard = t[0];
  w.total_normal_impulse = t[1];
  w.total_sliding_work = t[2];
  w.total_impulse = {t[3], t[4], t[5]};
  w.total_normal_moment = {t[6], t[7], t[8]};
  w.total_impulse_moment = {t[9], t[10], t[11]};
  return w;
}

} // namespace wear::dem
