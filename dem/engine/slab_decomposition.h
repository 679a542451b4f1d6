#pragma once
// One slab per rank along an angle about z or a Cartesian axis (the engine's SlabCuts), the
// check of the slabs against the interaction reach, and cuts that balance a cost histogram.
#include "dem/engine/rank_link.h"

#include <vector>

namespace wear::dem {

class SlabDecomposition final : public RankSlabs {
public:
  /// Angular slabs of the sector theta in [theta_0, theta_0 + angle) about z (angle = 2 pi:
  /// the full circle), measured against the reach as arcs at `inner_radius` [m], the smallest
  /// radius particles reach. `bound`: n_ranks + 1 increasing angles [rad].
  static SlabDecomposition angular(std::vector<double> bound, double inner_radius);
  /// Slabs along axis (0, 1, 2) at the `bound` [m] (n_ranks + 1, increasing).
  static SlabDecomposition along_axis(int axis, std::vector<double> bound);
  /// n_ranks equal slabs of [lo, hi) [rad or m].
  static std::vector<double> uniform_slabs(double lo, double hi, int n_ranks);
  /// n_ranks equal angular slabs of the sector [0, angle) [rad] (2 pi: the full circle),
  /// measured at `inner_radius` [m]: how the tester and the benchmark cut their beds.
  static SlabDecomposition uniform_angular(double angle, int n_ranks, double inner_radius);
  /// Bounds of n_ranks slabs of [lo, hi) that carry equal shares of `cost`, a histogram of
  /// equal bins over [lo, hi) (each bin's cost spread evenly over it). The histogram must be
  /// the same on every rank (summed over them), so that every rank places the same cuts.
  static std::vector<double> balanced_slabs(const std::vector<double>& cost, double lo, double hi,
                                            int n_ranks);

  const SlabCuts& cuts() const override { return cuts_; }
  void check_widths(double reach) const override;
  /// [m] Width of slab r: along the axis, or the arc at the inner radius.
  double width(int r) const;

private:
  SlabCuts cuts_;
  double inner_radius_ = 0; ///< [m] angular slabs only
};

} // namespace wear::dem
