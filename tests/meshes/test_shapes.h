#pragma once
// Small analytic shapes for the meshes tests.
#include "meshes/surface_mesh.h"

#include <cmath>
#include <functional>
#include <map>
#include <utility>
#include <vector>

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

/// The removed volume per face of a uniform depth [m] on the wearing faces.
inline std::vector<double> uniform_depth_volume(const SurfaceMesh& m, double depth) {
  const auto area = face_areas(m);
  std::vector<double> v(m.n_faces(), 0);
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    if (m.face_wears(f))
      v[f] = depth * area[f];
  return v;
}

/// A closed block over [0, lx] x [0, ly]: the top z = top(x, y) on an nx x ny grid of quads
/// (each cut along the same diagonal), the bottom z = 0 on the same grid, vertical sides
/// joining their edges. Top faces are labelled `top_label(x, y)` at their centroid, the bottom
/// label::bottom, the sides label::side.
inline SurfaceMesh height_field_block(int nx, int ny, double lx, double ly,
                                      const std::function<double(double, double)>& top,
                                      const std::function<int(double, double)>& top_label) {
  SurfaceMesh m;
  const auto id = [&](int i, int j, int layer) {
    return std::uint32_t(layer * (nx + 1) * (ny + 1) + i + (nx + 1) * j);
  };
  for (int layer = 0; layer < 2; ++layer)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const double x = lx * i / nx, y = ly * j / ny;
        m.vertices.push_back({x, y, layer == 1 ? top(x, y) : 0.0});
      }
  const auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, int label) {
    m.triangles.push_back({a, b, c});
    m.face_labels.push_back(label);
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double cx = lx * (i + 0.5) / nx, cy = ly * (j + 0.5) / ny;
      const int l = top_label(cx, cy);
      add(id(i, j, 1), id(i + 1, j, 1), id(i + 1, j + 1, 1), l);
      add(id(i, j, 1), id(i + 1, j + 1, 1), id(i, j + 1, 1), l);
      add(id(i, j, 0), id(i + 1, j + 1, 0), id(i + 1, j, 0), label::bottom);
      add(id(i, j, 0), id(i, j + 1, 0), id(i + 1, j + 1, 0), label::bottom);
    }
  // Sides: the boundary loop of the grid, counter-clockwise seen from above.
  std::vector<std::pair<int, int>> loop;
  for (int i = 0; i < nx; ++i)
    loop.push_back({i, 0});
  for (int j = 0; j < ny; ++j)
    loop.push_back({nx, j});
  for (int i = nx; i > 0; --i)
    loop.push_back({i, ny});
  for (int j = ny; j > 0; --j)
    loop.push_back({0, j});
  for (std::size_t e = 0; e < loop.size(); ++e) {
    const auto [i0, j0] = loop[e];
    const auto [i1, j1] = loop[(e + 1) % loop.size()];
    add(id(i0, j0, 0), id(i1, j1, 0), id(i1, j1, 1), label::side);
    add(id(i0, j0, 0), id(i1, j1, 1), id(i0, j0, 1), label::side);
  }
  return m;
}

/// A sphere of `radius` about the origin: an icosahedron subdivided `levels` times, projected.
inline SurfaceMesh icosphere(double radius, int levels) {
  SurfaceMesh m;
  const double t = (1 + std::sqrt(5.0)) / 2;
  for (const auto& v : {Vec3{-1, t, 0}, Vec3{1, t, 0}, Vec3{-1, -t, 0}, Vec3{1, -t, 0},
                        Vec3{0, -1, t}, Vec3{0, 1, t}, Vec3{0, -1, -t}, Vec3{0, 1, -t},
                        Vec3{t, 0, -1}, Vec3{t, 0, 1}, Vec3{-t, 0, -1}, Vec3{-t, 0, 1}})
    m.vertices.push_back(normalized(v) * radius);
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    const auto middle = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end())
        return it->second;
      m.vertices.push_back(normalized(m.vertices[a] + m.vertices[b]) * radius);
      return mid[key] = std::uint32_t(m.vertices.size() - 1);
    };
    std::vector<Triangle> finer;
    for (const auto& [a, b, c] : m.triangles) {
      const auto ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      finer.push_back({a, ab, ca});
      finer.push_back({b, bc, ab});
      finer.push_back({c, ca, bc});
      finer.push_back({ab, bc, ca});
    }
    m.triangles = finer;
  }
  m.face_labels.assign(m.triangles.size(), label::wall);
  return m;
}

} // namespace wear::meshes::testing
