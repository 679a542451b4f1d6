// Matching boundary faces to surface triangles: each triangle is keyed by its three vertex
// positions quantised to 1e-9 of the bounding-box diagonal (sorted), which is far below any
// mesh size and far above the round-off of a mesh written and read back.
#include "fem/boundary_face_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

namespace wear::fem {

namespace {
using Key = std::array<std::int64_t, 9>;

Key make_key(std::array<meshes::Vec3, 3> v, double q) {
  std::sort(v.begin(), v.end(), [](const meshes::Vec3& a, const meshes::Vec3& b) {
    return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
  });
  Key k;
  for (int i = 0; i < 3; ++i)
    for (int d = 0; d < 3; ++d)
      k[3 * i + d] = std::llround(v[i][d] / q);
  return k;
}
} // namespace

meshes::SurfaceMesh extract_boundary_surface(const dealii::Triangulation<3>& tria) {
  meshes::SurfaceMesh m;
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
  const auto bb = meshes::bounding_box(surface);
  const double q = 1e-9 * meshes::norm(bb.extent());
  std::map<Key, std::size_t> index;
  for (std::size_t f = 0; f < surface.n_faces(); ++f) {
    const auto& t = surface.triangles[f];
    index[make_key({surface.vertices[t[0]], surface.vertices[t[1]], surface.vertices[t[2]]}, q)] =
        f;
  }
  faces_.resize(surface.n_faces());
  vertex_.assign(surface.n_vertices(), ~0u);
  std::vector<char> found(surface.n_faces(), 0);
  std::size_t n_boundary = 0;
  for (const auto& cell : tria.active_cell_iterators())
    for (const auto f : cell->face_indices()) {
      if (!cell->face(f)->at_boundary())
        continue;
      ++n_boundary;
      const auto face = cell->face(f);
      std::array<meshes::Vec3, 3> v;
      for (unsigned int k = 0; k < 3; ++k)
        v[k] = {face->vertex(k)[0], face->vertex(k)[1], face->vertex(k)[2]};
      const auto it = index.find(make_key(v, q));
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
      for (const auto sv : surface.triangles[it->second])
        for (unsigned int k = 0; k < 3; ++k)
          if (meshes::norm2(surface.vertices[sv] - v[k]) <= q * q * 16)
            vertex_[sv] = face->vertex_index(k);
    }
  for (std::size_t f = 0; f < found.size(); ++f)
    if (!found[f])
      throw std::runtime_error("surface triangle " + std::to_string(f) +
                               " has no boundary face in the volume mesh");
  if (n_boundary != surface.n_faces())
    throw std::runtime_error("the volume mesh has " + std::to_string(n_boundary) +
                             " boundary faces, the surface " + std::to_string(surface.n_faces()));
}

} // namespace wear::fem
