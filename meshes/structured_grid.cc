// Structured triangulation of a parametric patch. Vertex (i, j) sits at
// point(i / n_u, j / n_v); quads are split in two along a diagonal chosen per quad.
#include "meshes/structured_grid.h"

namespace wear::meshes {

SurfaceMesh structured_grid(int n_u, int n_v, const std::function<Vec3(double, double)>& point,
                            bool flip, int label_id, Diagonals diagonals) {
  SurfaceMesh m;
  for (int j = 0; j <= n_v; ++j)
    for (int i = 0; i <= n_u; ++i)
      m.vertices.push_back(point(double(i) / n_u, double(j) / n_v));
  const auto id = [&](int i, int j) { return static_cast<std::uint32_t>(j * (n_u + 1) + i); };
  const auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    m.triangles.push_back(flip ? Triangle{a, c, b} : Triangle{a, b, c});
    m.face_labels.push_back(label_id);
  };
  for (int j = 0; j < n_v; ++j)
    for (int i = 0; i < n_u; ++i) {
      if (diagonals == Diagonals::uniform || (i + j) % 2 == 0) {
        add(id(i, j), id(i + 1, j), id(i + 1, j + 1));
        add(id(i, j), id(i + 1, j + 1), id(i, j + 1));
      } else {
        add(id(i, j), id(i + 1, j), id(i, j + 1));
        add(id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
      }
    }
  return m;
}

} // namespace wear::meshes
