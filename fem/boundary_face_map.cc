// Matching boundary faces to surface triangles: vertices are matched within 1e-9 of the
// bounding-box diagonal (far below any mesh size, far above the round-off of a mesh written
// as text and read back), then faces by their sorted vertex triples.
#include "fem/boundary_face_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

namespace wear::fem {

namespace {
using Cell = std::array<std::int64_t, 3>;
Cell cell_of(const meshes::Vec3& p, double h) {
  return {std::int64_t(std::floor(p.x / h)), std::int64_t(std::floor(p.y / h)),
          std::int64_t(std::floor(p.z / h))};
}
} // namespace

meshes::SurfaceMesh extract_boundary_surface(const dealii::Triangulation<3>& tria,
                                             const meshes::LabelRoles& roles) {
  meshes::SurfaceMesh m;
  m.roles = roles;
  std::map<unsigned int, std::uint32_t> vertex;
  for (const auto& cell : tria.active_cell_iterators())
    for (const auto f : cell->face_indices()) {
      if (!cell->face(f)->at_boundary())
        continue;
      const auto face = cell->face(f);
      meshes::Triangle t;
      for (unsigned int k = 0; k < 3; ++k) {
        const auto [it, added] =
            vertex.emplace(face->vertex_index(k), std::uint32_t(m.vertices.size()));
        if (added)
          m.vertices.push_back({face->vertex(k)[0], face->vertex(k)[1], face->vertex(k)[2]});
        t[k] = it->second;
      }
      // Outward: the normal points away from the cell's centre.
      const auto c = cell->center();
      const meshes::Vec3 centre{c[0], c[1], c[2]};
      const auto &a = m.vertices[t[0]], &b = m.vertices[t[1]], &d = m.vertices[t[2]];
      if (meshes::dot(meshes::cross(b - a, d - a), a - centre) < 0)
        std::swap(t[1], t[2]);
      m.triangles.push_back(t);
      m.face_labels.push_back(int(face->boundary_id()));
    }
  return m;
}

BoundaryFaceMap::BoundaryFaceMap(const dealii::Triangulation<3>& tria,
                                 const meshes::SurfaceMesh& surface)
    : surface_(surface) {
  // Vertices first: each boundary vertex of the triangulation is matched to the surface
  // vertex within tol of it, searched in the 27 hash cells of size tol around it, so a
  // difference of round-off (a mesh written as text and read back) never splits a match.
  const auto bb = meshes::bounding_box(surface);
  const double tol = 1e-9 * meshes::norm(bb.extent());
  std::map<Cell, std::vector<std::uint32_t>> grid;
  for (std::size_t v = 0; v < surface.n_vertices(); ++v)
    grid[cell_of(surface.vertices[v], tol)].push_back(std::uint32_t(v));
  vertex_.assign(surface.n_vertices(), ~0u);
  std::map<unsigned int, std::uint32_t> surface_vertex; // triangulation -> surface
  const auto match = [&](unsigned int tv, const dealii::Point<3>& p) -> std::uint32_t {
    const auto known = surface_vertex.find(tv);
    if (known != surface_vertex.end())
      return known->second;
    const meshes::Vec3 x{p[0], p[1], p[2]};
    const Cell c = cell_of(x, tol);
    std::uint32_t best = ~0u;
    double best_d2 = tol * tol;
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j)
        for (int k = -1; k <= 1; ++k) {
          const auto it = grid.find({c[0] + i, c[1] + j, c[2] + k});
          if (it == grid.end())
            continue;
          for (const auto v : it->second) {
            const double d2 = meshes::norm2(surface.vertices[v] - x);
            if (d2 <= best_d2) {
              best_d2 = d2;
              best = v;
            }
          }
        }
    surface_vertex[tv] = best;
    if (best != ~0u)
      vertex_[best] = tv;
    return best;
  };
  std::map<std::array<std::uint32_t, 3>, std::size_t> index;
  for (std::size_t f = 0; f < surface.n_faces(); ++f) {
    auto t = surface.triangles[f];
    std::sort(t.begin(), t.end());
    index[{t[0], t[1], t[2]}] = f;
  }
  faces_.resize(surface.n_faces());
  std::vector<char> found(surface.n_faces(), 0);
  std::size_t n_boundary = 0;
  for (const auto& cell : tria.active_cell_iterators())
    for (const auto f : cell->face_indices()) {
      if (!cell->face(f)->at_boundary())
        continue;
      ++n_boundary;
      const auto face = cell->face(f);
      std::array<std::uint32_t, 3> t;
      for (unsigned int k = 0; k < 3; ++k)
        t[k] = match(face->vertex_index(k), face->vertex(k));
      std::sort(t.begin(), t.end());
      const auto it = t[2] == ~0u ? index.end() : index.find(t);
      if (it == index.end())
        throw std::runtime_error("boundary face of cell " +
                                 std::to_string(cell->active_cell_index()) +
                                 " has no matching triangle in the surface mesh");
      if (int(face->boundary_id()) != surface.face_labels[it->second])
        throw std::runtime_error("surface triangle " + std::to_string(it->second) + " has label " +
                                 std::to_string(surface.face_labels[it->second]) +
                                 " but its boundary face has id " +
                                 std::to_string(face->boundary_id()));
      faces_[it->second] = {cell, f};
      found[it->second] = 1;
    }
  for (std::size_t f = 0; f < found.size(); ++f)
    if (!found[f])
      throw std::runtime_error("surface triangle " + std::to_string(f) +
                               " has no boundary face in the volume mesh");
  if (n_boundary != surface.n_faces())
    throw std::runtime_error("the volume mesh has " + std::to_string(n_boundary) +
                             " boundary faces, the surface " + std::to_string(surface.n_faces()));
}

void BoundaryFaceMap::follow(const dealii::Triangulation<3>& tria, meshes::SurfaceMesh moved) {
  if (moved.n_faces() != surface_.n_faces() || moved.n_vertices() != surface_.n_vertices())
    throw std::invalid_argument("boundary face map: the moved surface has another topology; "
                                "build a new map");
  const auto& points = tria.get_vertices();
  for (std::size_t v = 0; v < moved.n_vertices(); ++v)
    for (int d = 0; d < 3; ++d)
      moved.vertices[v][d] = points[vertex_[v]][d];
  surface_ = std::move(moved);
}

} // namespace wear::fem
