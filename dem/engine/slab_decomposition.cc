// Slabs of a DEM bed over ranks (SlabDecomposition).
//
// Width check: a particle interacts with partners within the reach 2 r_max + skin of its
// centre (the neighbour lists' cut-off at the largest size), and the engine exchanges
// particles and ghosts with the adjacent ranks only. So every slab must be at least the reach
// wide: then no particle of rank r - 1 comes within reach of one of rank r + 1, and a particle
// moves at most one slab between two list rebuilds (half a skin). An angular slab is
// narrowest at the smallest radius particles reach, so it is measured as the arc
// (theta_{r+1} - theta_r) r_inner there; the most ranks that fit is floor(total / reach).
//
// Balanced cuts: with C(s) the cumulative cost along the coordinate (piecewise linear over the
// histogram's bins), cut k lies where C = k C_total / n_ranks.
#include "dem/engine/slab_decomposition.h"

#include "meshes/constants.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wear::dem {

namespace {
void check_bounds(const std::vector<double>& bound) {
  if (bound.size() < 2)
    throw std::invalid_argument("SlabDecomposition: at least two bounds (one slab) are needed");
  for (std::size_t k = 0; k + 1 < bound.size(); ++k)
    if (!(bound[k] < bound[k + 1]))
      throw std::invalid_argument("SlabDecomposition: the bounds must increase");
}
} // namespace

SlabDecomposition SlabDecomposition::angular(std::vector<double> bound, double inner_radius) {
  check_bounds(bound);
  if (bound.back() - bound.front() > 2 * pi + 1e-12)
    throw std::invalid_argument("SlabDecomposition: the slabs span more than the full circle");
  if (!(inner_radius >= 0))
    throw std::invalid_argument("SlabDecomposition: the inner radius must not be negative");
  SlabDecomposition d;
  d.cuts_.angular = true;
  d.cuts_.bound = std::move(bound);
  d.inner_radius_ = inner_radius;
  return d;
}

SlabDecomposition SlabDecomposition::along_axis(int axis, std::vector<double> bound) {
  check_bounds(bound);
  if (axis < 0 || axis > 2)
    throw std::invalid_argument("SlabDecomposition: the axis must be 0, 1 or 2");
  SlabDecomposition d;
  d.cuts_.axis = axis;
  d.cuts_.bound = std::move(bound);
  return d;
}

std::vector<double> SlabDecomposition::uniform_slabs(double lo, double hi, int n_ranks) {
  std::vector<double> b(std::size_t(n_ranks) + 1);
  for (int r = 0; r <= n_ranks; ++r)
    b[std::size_t(r)] = lo + (hi - lo) * r / n_ranks;
  b.back() = hi;
  return b;
}

SlabDecomposition SlabDecomposition::uniform_angular(double angle, int n_ranks,
                                                     double inner_radius) {
  return angular(uniform_slabs(0, angle, n_ranks), inner_radius);
}

std::vector<double> SlabDecomposition::balanced_slabs(const std::vector<double>& cost, double lo,
                                                      double hi, int n_ranks) {
  if (cost.empty() || n_ranks < 1)
    throw std::invalid_argument("SlabDecomposition: an empty cost histogram or no rank");
  double total = 0;
  for (double c : cost)
    total += c;
  if (!(total > 0))
    return uniform_slabs(lo, hi, n_ranks);
  const double bin = (hi - lo) / double(cost.size());
  std::vector<double> b{lo};
  double below = 0; // cost of the bins before k
  std::size_t k = 0;
  for (int r = 1; r < n_ranks; ++r) {
    const double target = total * r / n_ranks;
    while (k + 1 < cost.size() && below + cost[k] < target)
      below += cost[k++];
    const double within = cost[k] > 0 ? std::min(1.0, (target - below) / cost[k]) : 0.0;
    b.push_back(std::max(b.back(), lo + bin * (double(k) + within)));
  }
  b.push_back(hi);
  return b;
}

double SlabDecomposition::width(int r) const {
  const double w = cuts_.bound[std::size_t(r) + 1] - cuts_.bound[std::size_t(r)];
  return cuts_.angular ? w * inner_radius_ : w;
}

void SlabDecomposition::check_widths(double reach) const {
  const int n = cuts_.n_ranks();
  if (n < 2)
    return;
  int narrowest = 0;
  for (int r = 1; r < n; ++r)
    if (width(r) < width(narrowest))
      narrowest = r;
  if (width(narrowest) >= reach)
    return;
  double total = 0;
  for (int r = 0; r < n; ++r)
    total += width(r);
  std::ostringstream s;
  s << "DEM over " << n << " ranks: slab " << narrowest << " is " << width(narrowest) << " m wide"
    << (cuts_.angular ? " (arc at the inner radius)" : "")
    << ", narrower than the interaction reach " << reach
    << " m (two largest radii and the skin); the bed (" << total
    << " m across) can be cut into at most " << std::max(1, int(std::floor(total / reach)))
    << " slabs that wide";
  throw std::invalid_argument(s.str());
}

} // namespace wear::dem
