#pragma once
// The engine's view of a bed decomposed over ranks (processes), without MPI: the slabs that
// say which rank owns a point, and the messages between neighbouring ranks. dem/parallel
// implements the messages over MPI (MpiRankLink), slab_decomposition.h cuts the slabs; the
// engine never includes mpi.h.
#include "meshes/constants.h"
#include "meshes/vec3.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace wear::dem {

using meshes::Vec3;

/// One slab per rank along one coordinate: rank r owns the points whose coordinate lies in
/// [bound[r], bound[r + 1]); points below bound[0] belong to rank 0, beyond the last bound to
/// the last rank. A plain struct, so that the owner of a particle costs no virtual call.
struct SlabCuts {
  /// true: the coordinate is theta = atan2(y, x) about the z axis, taken in [bound[0] - gap/2,
  /// bound[0] + 2 pi - gap/2) with gap = 2 pi - (bound.back() - bound[0]) (the gap outside a
  /// sector split at its middle); false: the Cartesian coordinate x_axis.
  bool angular = false;
  int axis = 0;              ///< 0, 1, 2 for Cartesian slabs
  std::vector<double> bound; ///< [rad] or [m] n_ranks + 1 values, increasing

  int n_ranks() const { return int(bound.size()) - 1; }
  /// [rad] or [m] the slab coordinate of x.
  double coordinate(const Vec3& x) const {
    if (!angular)
      return x[axis];
    constexpr double two_pi = 2 * pi;
    const double gap = two_pi - (bound.back() - bound.front());
    double theta = std::atan2(x.y, x.x);
    while (theta < bound.front() - 0.5 * gap)
      theta += two_pi;
    while (theta >= bound.front() - 0.5 * gap + two_pi)
      theta -= two_pi;
    return theta;
  }
  /// The rank that owns point x.
  int owner(const Vec3& x) const {
    const double c = coordinate(x);
    return int(std::upper_bound(bound.begin() + 1, bound.end() - 1, c) - (bound.begin() + 1));
  }
  /// [m] How far x lies below the upper cut of rank r (negative beyond it): along the axis, or
  /// the distance to the half-plane from the z axis at theta = bound[r + 1] (a point behind the
  /// axis, more than 90 degrees from it, is as far as the axis: a slab over 180 degrees wide
  /// has its lower cut on the same plane, on the other side).
  double below_upper_cut(int r, const Vec3& x) const {
    const double cut = bound[std::size_t(r) + 1];
    if (!angular)
      return cut - x[axis];
    const double c = std::cos(cut), s = std::sin(cut);
    return c * x.x + s * x.y >= 0 ? s * x.x - c * x.y : std::hypot(x.x, x.y);
  }
};

/// The messages of a rank with its neighbours (rank - 1 below, rank + 1 above; on a line the
/// first rank has none below and the last none above, on a ring they are each other's) and the
/// reductions over all ranks. One virtual call per message; buffers keep their storage (the step
/// loop allocates nothing once they grew).
class RankLink {
public:
  virtual ~RankLink() = default;
  virtual int rank() const = 0;
  virtual int n_ranks() const = 0;
  /// True when the ranks form a ring: the last rank's neighbour above is rank 0 (a periodic
  /// sector or slab, whose seam joins them).
  virtual bool ring() const = 0;
  /// Sends `send` to the neighbour in `direction` (+1 above, -1 below) and receives into
  /// `receive` what the opposite neighbour sent in the same direction (empty without one).
  /// Every rank calls it together.
  virtual void shift(int direction, const std::vector<double>& send,
                     std::vector<double>& receive) = 0;
  /// values[k] becomes the largest over the ranks (every rank gets the same).
  virtual void max_over_ranks(double* values, std::size_t n) = 0;
  /// values[k] becomes the sum over the ranks, added in rank order 0, 1, 2, ... (every rank
  /// gets the same bits, independently of timing).
  virtual void sum_in_rank_order(double* values, std::size_t n) = 0;
  /// `all` becomes every rank's `mine` one after the other in rank order 0, 1, 2, ... (every
  /// rank gets the same). For evaluations over a few particles, not for the step loop.
  virtual void gather_in_rank_order(const std::vector<double>& mine, std::vector<double>& all) = 0;
  /// On rank 0 `all` becomes every rank's `mine` one after the other in rank order and
  /// `counts` their sizes; on the other ranks both come back empty. Every rank calls it
  /// together. For checkpoints: one rank holds the whole bed once, no rank every other's.
  virtual void gather_to_first(const std::vector<double>& mine, std::vector<double>& all,
                               std::vector<std::size_t>& counts) = 0;
};

/// The decomposition as the engine takes it at setup: the slabs, and the check of their widths
/// against the interaction reach, which is known only once every rank's particles are.
class RankSlabs {
public:
  virtual ~RankSlabs() = default;
  virtual const SlabCuts& cuts() const = 0;
  /// Throws std::invalid_argument when a slab is narrower than `reach` [m] (a particle could
  /// then touch one two ranks away), naming the rank count, the narrowest width, the reach and
  /// the most ranks that fit.
  virtual void check_widths(double reach) const = 0;
};

} // namespace wear::dem
