#pragma once
// Small analytic shapes for the meshes tests.
#include "meshes/surface_mesh.h"

namespace wear::meshes::testing {

/// Axis-aligned box [0,a]x[0,b]x[0,c], 12 outward triangles.
inline SurfaceMesh box(double a = 1, double b = 1, double c = 1) {
  SurfaceMesh m;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        m.vertices.push_back({i * a, j * b, k * c});
  const auto v = [](int i, int j, int k) { return std::uint32_t(i + 2 * j + 4 * k); };
  const auto quad = [&](std::uint32_t p, std::uint32_t q, std::uint32_t r, std::uint32_t s) {
    m.triangles.push_back({p, q, r});
    m.triangles.push_back({p, r, s});
  };
  quad(v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0)); // z = 0, normal -z
  quad(v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1)); // z = c, normal +z
  quad(v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1)); // y = 0, normal -y
  quad(v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0)); // y = b, normal +y
  quad(v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0)); // x = 0, normal -x
  quad(v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1)); // x = a, normal +x
  m.face_labels.assign(m.triangles.size(), label::wall);
  return m;
}

} // namespace wear::meshes::testing
