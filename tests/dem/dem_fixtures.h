#pragma once
// Shared set-ups for the DEM tests.
#include "dem/filling.h"
#include "dem/system.h"
#include "meshes/tester_walls.h"

#include <cmath>

namespace wear::dem::testing {

constexpr double pi = 3.14159265358979323846;

/// Inward-facing closed box [0, L]^3 as one wall mesh.
inline meshes::SurfaceMesh box_walls(double L) {
  meshes::SurfaceMesh m;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        m.vertices.push_back({i * L, j * L, k * L});
  const auto v = [](int i, int j, int k) { return std::uint32_t(i + 2 * j + 4 * k); };
  const auto quad = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    m.triangles.push_back({a, b, c});
    m.triangles.push_back({a, c, d});
  };
  quad(v(0, 0, 0), v(1, 0, 0), v(1, 1, 0), v(0, 1, 0));
  quad(v(0, 0, 1), v(0, 1, 1), v(1, 1, 1), v(1, 0, 1));
  quad(v(0, 0, 0), v(0, 0, 1), v(1, 0, 1), v(1, 0, 0));
  quad(v(0, 1, 0), v(1, 1, 0), v(1, 1, 1), v(0, 1, 1));
  quad(v(0, 0, 0), v(0, 1, 0), v(0, 1, 1), v(0, 0, 1));
  quad(v(1, 0, 0), v(1, 0, 1), v(1, 1, 1), v(1, 1, 0));
  m.face_labels.assign(m.triangles.size(), meshes::label::wall);
  return m;
}

/// Gravel-like material of the anchor workload (E = 5e7 Pa, nu = 0.25, rho = 2650).
inline int add_gravel(System& s, double e, double mu, double mu_r) {
  const int g = s.materials.add({"gravel", 5e7, 0.25, 2650});
  s.materials.set_pair(g, g, {e, mu, mu_r});
  return g;
}

} // namespace wear::dem::testing
