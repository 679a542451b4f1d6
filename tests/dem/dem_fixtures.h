#pragma once
// Shared set-ups for the DEM tests.
#include "dem/engine/filling.h"
#include "dem/engine/system.h"
#include "meshes/constants.h"
#include "meshes/structured_grid.h"
#include "meshes/tester_walls.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>

namespace wear::dem::testing {

using wear::pi;

/// The planes y = 0, y = L, z = 0, z = L facing inwards, reaching `margin` past x = 0 and
/// x = L: a closed box [0, L]^3 with `closed` (the planes x = 0 and x = L too, no margin), else
/// a channel along x (for a period along x).
inline meshes::SurfaceMesh box_or_channel(double L, bool closed, double margin) {
  meshes::SurfaceMesh m;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        m.vertices.push_back({closed ? i * L : (i ? L + margin : -margin), j * L, k * L});
  const auto v = [](int i, int j, int k) { return std::uint32_t(i + 2 * j + 4 * k); };
  const auto quad = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    m.triangles.push_back({a, b, c});
    m.triangles.push_back({a, c, d});
  };
  quad(v(0, 0, 0), v(1, 0, 0), v(1, 1, 0), v(0, 1, 0));
  quad(v(0, 0, 1), v(0, 1, 1), v(1, 1, 1), v(1, 0, 1));
  quad(v(0, 0, 0), v(0, 0, 1), v(1, 0, 1), v(1, 0, 0));
  quad(v(0, 1, 0), v(1, 1, 0), v(1, 1, 1), v(0, 1, 1));
  if (closed) {
    quad(v(0, 0, 0), v(0, 1, 0), v(0, 1, 1), v(0, 0, 1));
    quad(v(1, 0, 0), v(1, 0, 1), v(1, 1, 1), v(1, 1, 0));
  }
  m.face_labels.assign(m.triangles.size(), meshes::label::wall);
  return m;
}

/// Inward-facing closed box [0, L]^3 as one wall mesh.
inline meshes::SurfaceMesh box_walls(double L) {
  return box_or_channel(L, true, 0);
}

/// Gravel-like material of the anchor workload (E = 5e7 Pa, nu = 0.25, rho = 2650).
/// The flat square [-L, L]^2 at height z with n x n quads split by `diagonals`, normal +z,
/// labelled as a sample's base.
inline meshes::SurfaceMesh flat_square(double L, int n, double z = 0,
                                       meshes::Diagonals diagonals = meshes::Diagonals::uniform) {
  return meshes::structured_grid(
      n, n,
      [L, z](double u, double v) {
        return meshes::Vec3{-L + 2 * L * u, -L + 2 * L * v, z};
      },
      false, meshes::label::base, diagonals);
}

inline int add_gravel(System& s, double e, double mu, double mu_r) {
  const int g = s.materials.add({"gravel", 5e7, 0.25, 2650});
  s.materials.set_pair(g, g, {e, mu, mu_r});
  return g;
}

/// The tester's walls (0.1 m high, 20 mm mesh, no consolidator) as a periodic sector of
/// `angle_deg`, the floor turning at 90 deg/s and the cylinders too if `rotating_cylinders`.
inline void add_periodic_tester_sector(System& s, int material, double angle_deg,
                                       bool rotating_cylinders, bool wearing_floor = false) {
  meshes::TesterGeometry t;
  t.sector_angle_deg = angle_deg;
  t.wall_height = 0.1;
  t.wall_mesh_size = 0.02;
  t.consolidator = false;
  const auto w = meshes::generate_tester_walls(t);
  WallMotion rot;
  rot.angular_velocity = 0.5 * pi; // 90 deg/s
  const WallMotion cylinders = rotating_cylinders ? rot : WallMotion{};
  s.add_wall(MeshWall(w.floor, material, rot, wearing_floor, "floor"));
  s.add_wall(MeshWall(w.inner, material, cylinders, false, "inner"));
  s.add_wall(MeshWall(w.outer, material, cylinders, false, "outer"));
  s.settings.periodic = {true, angle_deg * pi / 180};
  s.settings.domain = {{-0.6, -0.6, -0.01}, {0.6, 0.6, 0.5}};
}

/// Adds the real particles of `from` as they are there, stable ids included (as
/// WearTester::restore does before importing the state).
inline void add_particles_of(Particles& p, const SystemState& from) {
  for (std::size_t i = 0; i < from.position.size(); ++i) {
    p.add(from.position[i], from.velocity[i], from.radius[i], 2650, from.material[i]);
    p.id.back() = from.id[i];
  }
}

/// Two systems that must have run identically: particles, forces and contact histories bit
/// for bit.
inline void check_same_particles(const System& a, const System& c) {
  const auto sa = a.export_state(), sc = c.export_state();
  REQUIRE(sa.position.size() == sc.position.size());
  CHECK(sa.position == sc.position);
  CHECK(sa.velocity == sc.velocity);
  CHECK(sa.angular_velocity == sc.angular_velocity);
  CHECK(sa.force == sc.force);
  CHECK(sa.pair_history == sc.pair_history);
  CHECK(sa.slot_delta == sc.slot_delta);
}

/// The same, and the same wear window on wall 0, a wearing wall that has seen contacts.
inline void check_same_state(const System& a, const System& c) {
  check_same_particles(a, c);
  const auto wa = a.wear_integrals(0), wc = c.wear_integrals(0);
  CHECK(wa.total_archard > 0);
  CHECK(wa.archard == wc.archard);
  CHECK(wa.impulse == wc.impulse);
  CHECK(wa.contact_steps == wc.contact_steps);
}

} // namespace wear::dem::testing
