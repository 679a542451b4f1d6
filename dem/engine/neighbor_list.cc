// Neighbour list by cell binning.
//
// Cells are cubes of edge >= 2 r_max + skin, so every partner of a particle lies in its own
// or the 26 surrounding cells. Particles are binned by a counting sort (cell_start_ is a CSR
// index). One parallel pass: each thread scans a contiguous range of particles into its own
// buffers, which are concatenated in thread order; each particle's partners are sorted, so the
// list is identical for any thread count.
#include "dem/engine/neighbor_list.h"
#include "dem/engine/reused_buffer.h"

#include "meshes/surface_mesh.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace wear::dem {

/// Cubic cells over the bounding box of the real and ghost slots, of edge >= 2 r_max + skin.
struct NeighborList::CellGrid {
  Vec3 lo;     ///< [m] lowest corner
  double cell; ///< [m] edge
  int nx, ny, nz;
  /// Cell coordinate along axis d of n cells.
  int coord(const Vec3& x, int d, int n) const {
    return std::min(n - 1, int((x[d] - lo[d]) / cell));
  }
  std::size_t n_cells() const { return std::size_t(nx) * ny * nz; }
};

NeighborList::CellGrid NeighborList::make_grid(const Particles& p, double skin) {
  const std::size_t n_all = p.position.size();
  const double r_max = *std::max_element(p.radius.begin(), p.radius.begin() + n_all);
  const auto box = meshes::bounding_box(p.position.data(), n_all);
  double cell = 2 * r_max + skin;
  const Vec3 ext = box.extent();
  // Bound the cell count by a few per particle for sparse or spread-out systems.
  while ((ext.x / cell + 1) * (ext.y / cell + 1) * (ext.z / cell + 1) > 8.0 * n_all + 64)
    cell *= 1.26;
  return {box.min, cell, int(ext.x / cell) + 1, int(ext.y / cell) + 1, int(ext.z / cell) + 1};
}

void NeighborList::build(const Particles& p, double skin) {
  if (p.position.empty()) { // a rank of a decomposed bed may hold nothing
    pair_i.clear();
    pair_j.clear();
    return;
  }
  const CellGrid grid = make_grid(p, skin);
  bin(p, grid);
  // One pass: each thread takes a contiguous range of particles and appends to its own
  // buffers; concatenating them in thread order gives the serial order.
  int n_threads = 1;
#pragma omp parallel
  {
#pragma omp single
    {
      n_threads = omp_get_num_threads();
      chunk_i_.resize(n_threads);
      chunk_j_.resize(n_threads);
      chunk_scan_.resize(n_threads);
    }
    const int t = omp_get_thread_num();
    auto& ci = chunk_i_[t];
    auto& cj = chunk_j_[t];
    ci.clear();
    cj.clear();
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < p.n_real; ++i) {
      const std::size_t m = list_partners(p, grid, skin, i, chunk_scan_[t], cj);
      ci.insert(ci.end(), m, static_cast<std::uint32_t>(i));
    }
  }
  concatenate(n_threads);
}

void NeighborList::bin(const Particles& p, const CellGrid& grid) {
  const std::size_t n_all = p.position.size(), n_cells = grid.n_cells();
  const int nx = grid.nx, ny = grid.ny, nz = grid.nz;
  cell_of_.resize(n_all);
  assign_reusing(cell_start_, n_cells + 1, 0u); // the cell count follows the bed's extent
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n_all; ++i) {
    const Vec3& x = p.position[i];
    cell_of_[i] = static_cast<std::uint32_t>(
        (std::size_t(grid.coord(x, 2, nz)) * ny + grid.coord(x, 1, ny)) * nx +
        grid.coord(x, 0, nx));
  }
  for (std::size_t i = 0; i < n_all; ++i)
    ++cell_start_[cell_of_[i] + 1];
  for (std::size_t c = 0; c < n_cells; ++c)
    cell_start_[c + 1] += cell_start_[c];
  cell_items_.resize(n_all);
  resize_reusing(offset_, n_cells); // fill cursor
  std::copy(cell_start_.begin(), cell_start_.end() - 1, offset_.begin());
  for (std::size_t i = 0; i < n_all; ++i)
    cell_items_[offset_[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
  // Copies of the binned particles in cell order: the three cells of a stencil row are one
  // contiguous run, scanned without indirection.
  binned_.resize(n_all);
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < n_all; ++s) {
    const std::uint32_t o = cell_items_[s];
    binned_[s] = {p.position[o].x, p.position[o].y, p.position[o].z, p.radius[o]};
  }
}

inline std::size_t NeighborList::list_partners(const Particles& p, const CellGrid& grid,
                                               double skin, std::size_t i,
                                               std::vector<std::uint32_t>& scan,
                                               std::vector<std::uint32_t>& out) const {
  const int nx = grid.nx, ny = grid.ny, nz = grid.nz;
  const Vec3& xi = p.position[i];
  const double ri = p.radius[i] + skin;
  const int ci = grid.coord(xi, 0, nx), cj = grid.coord(xi, 1, ny), ck = grid.coord(xi, 2, nz);
  const int l0 = std::max(0, ci - 1), l1 = std::min(nx - 1, ci + 1);
  // The three cells of a stencil row are one run of cell_items_: at most 9 runs.
  std::uint32_t run_begin[9], run_end[9];
  int n_runs = 0;
  std::size_t n_candidates = 0;
  for (int k = std::max(0, ck - 1); k <= std::min(nz - 1, ck + 1); ++k)
    for (int j = std::max(0, cj - 1); j <= std::min(ny - 1, cj + 1); ++j) {
      const std::size_t row = (std::size_t(k) * ny + j) * nx;
      run_begin[n_runs] = cell_start_[row + l0];
      run_end[n_runs] = cell_start_[row + l1 + 1];
      n_candidates += run_end[n_runs] - run_begin[n_runs];
      ++n_runs;
    }
  // The candidates go to `scan`, which only grows: resizing `out` by the candidate count and
  // back would zero some 100 entries per particle to keep about 4.
  if (scan.size() < n_candidates)
    resize_reusing(scan, n_candidates);
  std::uint32_t* dst = scan.data();
  std::size_t m = 0;
  for (int r = 0; r < n_runs; ++r)
    // Branch-free: most candidates are rejected, unpredictably.
    for (auto s = run_begin[r]; s < run_end[r]; ++s) {
      const std::uint32_t o = cell_items_[s];
      const Binned& b = binned_[s];
      const double dx = b.x - xi.x, dy = b.y - xi.y, dz = b.z - xi.z;
      const double cut = ri + b.r;
      dst[m] = o;
      m += (dx * dx + dy * dy + dz * dz < cut * cut) & (o > i || o >= p.n_real);
    }
  std::sort(dst, dst + m);
  out.insert(out.end(), dst, dst + m);
  return m;
}

void NeighborList::concatenate(int n_threads) {
  std::size_t total = 0;
  offset_.assign(n_threads + 1, 0);
  for (int t = 0; t < n_threads; ++t)
    offset_[t + 1] = static_cast<std::uint32_t>(total += chunk_j_[t].size());
  pair_i.resize(total);
  pair_j.resize(total);
#pragma omp parallel for schedule(static, 1)
  for (int t = 0; t < n_threads; ++t) {
    std::copy(chunk_i_[t].begin(), chunk_i_[t].end(), pair_i.begin() + offset_[t]);
    std::copy(chunk_j_[t].begin(), chunk_j_[t].end(), pair_j.begin() + offset_[t]);
  }
}

void NeighborList::drop_pairs_within(const std::vector<std::int32_t>& group) {
  const std::size_t n = group.size();
  std::size_t kept = 0;
  for (std::size_t k = 0; k < pair_i.size(); ++k) {
    const std::uint32_t i = pair_i[k], j = pair_j[k];
    if (j < n && group[i] >= 0 && group[i] == group[j])
      continue;
    pair_i[kept] = i;
    pair_j[kept] = j;
    ++kept;
  }
  pair_i.resize(kept);
  pair_j.resize(kept);
}

} // namespace wear::dem
