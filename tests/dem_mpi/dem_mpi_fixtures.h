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
#include <cstdint>
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

/// [m] Radius of the test beds' spheres below; the reach is 2 r + r / 2 = 12.5 mm.
constexpr double bed_radius = 0.005;

/// Gravel (E = 5e7 Pa) on a floor z = 0 of [-0.1, 0.1] x [-0.05, 0.05] (20 x 10 quads).
inline int gravel_on_floor(System& s, bool wearing) {
  const int g = s.materials.add({"gravel", 5e7, 0.25, 2650});
  s.materials.set_pair(g, g, {0.5, 0.5, 0.1});
  s.add_wall(MeshWall(floor_mesh(-0.1, 0.1, -0.05, 0.05, 20, 10), g, {}, wearing, "floor"));
  s.settings.domain = {{-0.2, -0.2, -0.05}, {0.2, 0.2, 0.2}};
  return g;
}

/// Gravel (mu = 0.5 between grains) on a slippery floor (mu = 0.1) z = 0 of [-0.1, 0.1] x
/// [-0.05, 0.05] (20 x 10 quads), no rolling friction: a grain sliding on it turns, so grains
/// touching it and one another slip against each other. Returns the gravel's material.
inline int gravel_on_slippery_floor(System& s) {
  const int g = s.materials.add({"gravel", 5e7, 0.25, 2650});
  const int f = s.materials.add({"floor", 5e7, 0.25, 2650});
  s.materials.set_pair(g, g, {0.5, 0.5, 0.0});
  s.materials.set_pair(g, f, {0.5, 0.1, 0.0});
  s.materials.set_pair(f, f, {0.5, 0.1, 0.0});
  s.add_wall(MeshWall(floor_mesh(-0.1, 0.1, -0.05, 0.05, 20, 10), f, {}, false, "floor"));
  s.settings.domain = {{-0.2, -0.2, -0.05}, {0.2, 0.2, 0.2}};
  return g;
}

/// A square pyramid of 2 x 2 layers: 8 x 2 spheres on the floor, 7 x 1 in their hollows.
inline void pile(System& s, bool wearing) {
  const double r = bed_radius;
  const int g = gravel_on_floor(s, wearing);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 2; ++j)
      s.particles.add({-0.035 + 2 * r * i, 2 * r * j, r}, {}, r, 2650, g);
  for (int i = 0; i < 7; ++i)
    s.particles.add({-0.03 + 2 * r * i, r, r + r * std::sqrt(2.0)}, {}, r, 2650, g);
}

/// 343 spheres on a 12 mm lattice in a box of 0.1 m, no gravity, random velocities of about
/// 1 m/s (the same generator on every rank), e = 0.9, mu = 0.3; periodic along x if asked.
inline void gas(System& s, bool periodic) {
  const int g = s.materials.add({"gravel", 5e7, 0.25, 2650});
  s.materials.set_pair(g, g, {0.9, 0.3, 0.0});
  s.settings.gravity = {};
  s.settings.domain = {{-0.05, -0.01, -0.01}, {0.15, 0.11, 0.11}};
  if (periodic)
    s.settings.periodic_slab = {true, 0, 0.0, 0.1};
  std::uint64_t seed = 12345;
  const auto uniform = [&seed]() {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return double(seed >> 11) / double(std::uint64_t(1) << 53) - 0.5;
  };
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)
      for (int k = 0; k < 7; ++k)
        s.particles.add({0.014 + 0.012 * i, 0.014 + 0.012 * j, 0.014 + 0.012 * k},
                        {2 * uniform(), 2 * uniform(), 2 * uniform()}, bed_radius, 2650, g);
  s.add_wall(MeshWall(box_or_channel(0.1, !periodic, 0.01), g, {}, false, "box"));
}

} // namespace wear::dem::testing
