#pragma once
// Shared set-ups of the DEM-over-ranks tests: the ranks of MPI_COMM_WORLD, the bed's state
// gathered by stable id over the ranks, sums over the ranks, a flat floor of triangles.
#include "dem/engine/slab_decomposition.h"
#include "dem/engine/system.h"
#include "dem/parallel/mpi_rank_link.h"
#include "meshes/structured_grid.h"
#include "tests/dem/dem_fixtures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace wear::dem::testing {

inline MpiRankLink& world() {
  static MpiRankLink link(MPI_COMM_WORLD);
  return link;
}

/// The real particles' state over every rank, indexed by stable id (zero for an absent id).
struct BedState {
  std::vector<Vec3> x, v, w, f; ///< [m], [m/s], [rad/s], [N]
  std::vector<double> held;     ///< [-] how many ranks hold the id
  std::vector<double> rank;     ///< [-] the rank that holds it (summed over holders)
};

inline BedState gather(const System& s, std::size_t n_ids, RankLink& link) {
  constexpr std::size_t m = 14;
  std::vector<double> a(m * n_ids, 0.0);
  const auto& p = s.particles;
  for (std::size_t i = 0; i < p.n_real; ++i) {
    double* b = &a[m * std::size_t(p.id[i])];
    const Vec3 q[4] = {p.position[i], p.velocity[i], p.angular_velocity[i], p.force[i]};
    for (int k = 0; k < 4; ++k)
      b[3 * k] = q[k].x, b[3 * k + 1] = q[k].y, b[3 * k + 2] = q[k].z;
    b[12] = 1;
    b[13] = link.rank();
  }
  link.sum_in_rank_order(a.data(), a.size());
  BedState r;
  for (std::size_t id = 0; id < n_ids; ++id) {
    const double* b = &a[m * id];
    r.x.push_back({b[0], b[1], b[2]});
    r.v.push_back({b[3], b[4], b[5]});
    r.w.push_back({b[6], b[7], b[8]});
    r.f.push_back({b[9], b[10], b[11]});
    r.held.push_back(b[12]);
    r.rank.push_back(b[13]);
  }
  return r;
}

/// The same quantities of a System on one rank, by id.
inline BedState by_id(const System& s, std::size_t n_ids) {
  BedState r;
  r.x.assign(n_ids, {});
  r.v = r.w = r.f = r.x;
  r.held.assign(n_ids, 0);
  r.rank.assign(n_ids, 0);
  const auto& p = s.particles;
  for (std::size_t i = 0; i < p.n_real; ++i) {
    const auto id = std::size_t(p.id[i]);
    r.x[id] = p.position[i];
    r.v[id] = p.velocity[i];
    r.w[id] = p.angular_velocity[i];
    r.f[id] = p.force[i];
    r.held[id] = 1;
  }
  return r;
}

/// The largest |a - b| over the ids of a vector field.
inline double max_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double d = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    d = std::max(d, meshes::norm(a[k] - b[k]));
  return d;
}
inline double max_norm(const std::vector<Vec3>& a) {
  double d = 0;
  for (const Vec3& v : a)
    d = std::max(d, meshes::norm(v));
  return d;
}

/// Sum over the ranks, in rank order.
inline std::vector<double> over_ranks(std::vector<double> v, RankLink& link) {
  link.sum_in_rank_order(v.data(), v.size());
  return v;
}

/// Momentum [kg m/s] x 3, kinetic, rotational and elastic energy [J] of one rank's System.
inline std::vector<double> momentum_and_energy(const System& s) {
  const auto& p = s.particles;
  Vec3 m{};
  for (std::size_t i = 0; i < p.n_real; ++i)
    m += p.velocity[i] * p.mass[i];
  const Energy e = s.energy();
  return {m.x, m.y, m.z, e.kinetic, e.rotational, e.elastic};
}

/// The flat floor z = 0 over [x0, x1] x [y0, y1], nx x ny quads, normal +z.
inline meshes::SurfaceMesh floor_mesh(double x0, double x1, double y0, double y1, int nx, int ny) {
  return meshes::structured_grid(
      nx, ny,
      [=](double u, double v) {
        return Vec3{x0 + (x1 - x0) * u, y0 + (y1 - y0) * v, 0};
      },
      false, meshes::label::wall, meshes::Diagonals::uniform);
}

/// Slabs along x at the given bounds for the world's rank count (bounds[n_ranks - 1]).
inline SlabDecomposition x_slabs(const std::vector<std::vector<double>>& bounds) {
  return SlabDecomposition::along_axis(0, bounds.at(std::size_t(world().n_ranks()) - 1));
}

} // namespace wear::dem::testing
