// Binned continuum fields (binned_fields.h).
//
// Over the samples s of a window and the particles i whose centres lie in cell c:
//   solid fraction  phi_c = (1/S) sum_s sum_i V_i / V_c,   V_i = 4/3 pi r_i^3
//   velocity        v_c   = sum_s sum_i m_i v_i / sum_s sum_i m_i   (mass-weighted)
// Centre binning conserves the particle volume: sum_c phi_c V_c is the mean volume of the
// particles inside the grid. Over ranks each rank bins its own particles; the sums, not the
// means, are added over the ranks.
#include "dem/scene/binned_fields.h"

#include "meshes/constants.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace wear::dem {

Vec3 FieldGrid::spacing() const {
  return {(maximum.x - minimum.x) / cells[0], (maximum.y - minimum.y) / cells[1],
          (maximum.z - minimum.z) / cells[2]};
}

long FieldGrid::cell_of(const Vec3& x) const {
  const Vec3 h = spacing();
  const double u[3] = {(x.x - minimum.x) / h.x, (x.y - minimum.y) / h.y, (x.z - minimum.z) / h.z};
  long index[3];
  for (int d = 0; d < 3; ++d) {
    if (!(u[d] >= 0) || u[d] >= cells[d])
      return -1;
    index[d] = long(std::floor(u[d]));
  }
  return (index[2] * cells[1] + index[1]) * cells[0] + index[0];
}

BinnedFields::BinnedFields(const FieldGrid& grid) : grid_(grid) {
  for (int d = 0; d < 3; ++d) {
    if (!(grid.minimum[d] < grid.maximum[d]))
      throw std::invalid_argument("Scene/Fields: Minimum must lie below Maximum in every "
                                  "direction");
    if (grid.cells[d] < 1)
      throw std::invalid_argument("Scene/Fields/Cells: needs a count of at least 1 per "
                                  "direction, got " +
                                  std::to_string(grid.cells[d]));
  }
  reset();
}

void BinnedFields::sample(const Particles& p) {
  for (std::size_t i = 0; i < p.n_real; ++i) {
    const long c = grid_.cell_of(p.position[i]);
    if (c < 0)
      continue;
    const double r = p.radius[i];
    volume_[std::size_t(c)] += 4.0 / 3.0 * pi * r * r * r;
    mass_[std::size_t(c)] += p.mass[i];
    momentum_[std::size_t(c)] += p.mass[i] * p.velocity[i];
    count_[std::size_t(c)] += 1;
  }
  ++n_samples_;
}

BinnedWindow BinnedFields::window(RankLink* link) const {
  const std::size_t n = grid_.n_cells();
  if (link) { // the sums of every rank's particles, then the means of the one-rank path
    std::vector<double> sums;
    sums.reserve(6 * n);
    for (const auto* a : {&volume_, &mass_, &count_})
      sums.insert(sums.end(), a->begin(), a->end());
    for (const Vec3& m : momentum_)
      sums.insert(sums.end(), {m.x, m.y, m.z});
    link->sum_in_rank_order(sums.data(), sums.size());
    BinnedFields all(grid_);
    all.n_samples_ = n_samples_;
    std::copy(sums.begin(), sums.begin() + long(n), all.volume_.begin());
    std::copy(sums.begin() + long(n), sums.begin() + long(2 * n), all.mass_.begin());
    std::copy(sums.begin() + long(2 * n), sums.begin() + long(3 * n), all.count_.begin());
    for (std::size_t c = 0; c < n; ++c)
      all.momentum_[c] = {sums[3 * n + 3 * c], sums[3 * n + 3 * c + 1], sums[3 * n + 3 * c + 2]};
    return all.window();
  }
  BinnedWindow w;
  w.solid_fraction.assign(n, 0);
  w.velocity.assign(n, Vec3{});
  w.occupancy.assign(n, 0);
  w.n_samples = n_samples_;
  if (n_samples_ == 0)
    return w;
  const Vec3 h = grid_.spacing();
  const double cell_volume = h.x * h.y * h.z;
  for (std::size_t c = 0; c < n; ++c) {
    w.solid_fraction[c] = volume_[c] / (cell_volume * n_samples_);
    w.occupancy[c] = count_[c] / n_samples_;
    if (mass_[c] > 0)
      w.velocity[c] = momentum_[c] / mass_[c];
  }
  return w;
}

void BinnedFields::reset() {
  const std::size_t n = grid_.n_cells();
  volume_.assign(n, 0);
  mass_.assign(n, 0);
  count_.assign(n, 0);
  momentum_.assign(n, Vec3{});
  n_samples_ = 0;
}

} // namespace wear::dem
