// Neighbour list by cell binning.
//
// Cells are cubes of edge >= 2 r_max + skin, so every partner of a particle lies in its own
// or the 26 surrounding cells. Particles are binned by a counting sort (cell_start_ is a CSR
// index). Two passes over the real particles, each parallel and independent per particle,
// count then fill the pairs; each particle's partners are sorted so the list is identical for
// any thread count.
#include "dem/neighbor_list.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wear::dem {

void NeighborList::build(const Particles& p, double skin) {
  const std::size_t n_real = p.n_real, n_all = p.position.size();
  double r_max = 0;
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
          std::numeric_limits<double>::max()};
  Vec3 hi = lo * -1.0;
  for (std::size_t i = 0; i < n_all; ++i) {
    r_max = std::max(r_max, p.radius[i]);
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], p.position[i][d]);
      hi[d] = std::max(hi[d], p.position[i][d]);
    }
  }
  double cell = 2 * r_max + skin;
  const Vec3 ext = hi - lo;
  // Bound the cell count by a few per particle for sparse or spread-out systems.
  while ((ext.x / cell + 1) * (ext.y / cell + 1) * (ext.z / cell + 1) > 8.0 * n_all + 64)
    cell *= 1.26;
  const int nx = int(ext.x / cell) + 1, ny = int(ext.y / cell) + 1, nz = int(ext.z / cell) + 1;
  const std::size_t n_cells = std::size_t(nx) * ny * nz;
  const auto coord = [&](const Vec3& x, int d, int n) {
    return std::min(n - 1, int((x[d] - lo[d]) / cell));
  };
  cell_of_.resize(n_all);
  cell_start_.assign(n_cells + 1, 0);
  for (std::size_t i = 0; i < n_all; ++i) {
    const Vec3& x = p.position[i];
    cell_of_[i] = static_cast<std::uint32_t>(
        (std::size_t(coord(x, 2, nz)) * ny + coord(x, 1, ny)) * nx + coord(x, 0, nx));
    ++cell_start_[cell_of_[i] + 1];
  }
  for (std::size_t c = 0; c < n_cells; ++c)
    cell_start_[c + 1] += cell_start_[c];
  cell_items_.resize(n_all);
  {
    std::vector<std::uint32_t>& fill = offset_; // reused as a cursor
    fill.assign(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t i = 0; i < n_all; ++i)
      cell_items_[fill[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
  }
  count_.assign(n_real + 1, 0);
  const auto visit = [&](std::size_t i, auto&& emit) {
    const Vec3& xi = p.position[i];
    const int ci = coord(xi, 0, nx), cj = coord(xi, 1, ny), ck = coord(xi, 2, nz);
    for (int k = std::max(0, ck - 1); k <= std::min(nz - 1, ck + 1); ++k)
      for (int j = std::max(0, cj - 1); j <= std::min(ny - 1, cj + 1); ++j)
        for (int l = std::max(0, ci - 1); l <= std::min(nx - 1, ci + 1); ++l) {
          const std::size_t c = (std::size_t(k) * ny + j) * nx + l;
          for (auto s = cell_start_[c]; s < cell_start_[c + 1]; ++s) {
            const std::uint32_t o = cell_items_[s];
            if (o <= i && o < n_real)
              continue;
            const double cut = p.radius[i] + p.radius[o] + skin;
            if (meshes::norm2(p.position[o] - xi) < cut * cut)
              emit(o);
          }
        }
  };
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n_real; ++i) {
    std::uint32_t n = 0;
    visit(i, [&](std::uint32_t) { ++n; });
    count_[i + 1] = n;
  }
  for (std::size_t i = 0; i < n_real; ++i)
    count_[i + 1] += count_[i];
  pair_i.resize(count_[n_real]);
  pair_j.resize(count_[n_real]);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n_real; ++i) {
    std::uint32_t at = count_[i];
    visit(i, [&](std::uint32_t o) {
      pair_i[at] = static_cast<std::uint32_t>(i);
      pair_j[at++] = o;
    });
    std::sort(pair_j.begin() + count_[i], pair_j.begin() + count_[i + 1]);
  }
}

} // namespace wear::dem
