// Reads a worn sample with one stage's wear (worn_stage_file.h): the volume mesh, its boundary
// surface with labels and the stage's removed volume per face. The surface keeps the file's
// face order, so that the removed volume, a per-face extensive field, applies face for face;
// its vertices are the boundary's, renumbered in order of first use.
#include "coupling/output/worn_stage_file.h"

#include "coupling/output/hdf5_file.h"
#include "meshes/sample_generator.h"

#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

namespace wear::coupling {

WornStage read_worn_stage(const std::string& path) {
  const Hdf5Reader h5(path);
  WornStage s;
  auto& st = s.state;
  st.vertices = h5.doubles("vertices");
  const std::vector<std::int64_t> tetrahedra = h5.int64s("tetrahedra");
  const std::vector<int> triangles = h5.ints("triangles");
  const std::vector<int> labels = h5.ints("labels");
  s.removed_volume = h5.doubles("removed_volume");
  const auto fail = [&](const std::string& what) {
    throw std::runtime_error("worn stage file '" + path + "': " + what);
  };
  const std::size_t n_vertices = st.vertices.size() / 3;
  if (st.vertices.size() % 3 || tetrahedra.size() % 4 || triangles.size() != 3 * labels.size())
    fail("vertices, tetrahedra and triangles must hold 3, 4 and 3 entries a row, one label a "
         "triangle");
  if (s.removed_volume.size() != labels.size())
    fail("removed_volume has " + std::to_string(s.removed_volume.size()) + " entries for " +
         std::to_string(labels.size()) + " faces");
  for (const auto v : tetrahedra)
    if (v < 0 || std::size_t(v) >= n_vertices)
      fail("a tetrahedron names vertex " + std::to_string(v) + " of " + std::to_string(n_vertices));
  for (const int v : triangles)
    if (v < 0 || std::size_t(v) >= n_vertices)
      fail("a triangle names vertex " + std::to_string(v) + " of " + std::to_string(n_vertices));
  for (const double v : s.removed_volume)
    if (!std::isfinite(v) || v < 0)
      fail("removed_volume holds a negative or non-finite value");
  st.tetrahedra = tetrahedra;
  st.boundary_faces.assign(triangles.begin(), triangles.end());
  st.boundary_ids = labels;
  std::vector<int> surface_index(n_vertices, -1);
  auto& m = st.surface;
  for (std::size_t f = 0; f < labels.size(); ++f) {
    meshes::Triangle t;
    for (int k = 0; k < 3; ++k) {
      const int v = triangles[3 * f + k];
      if (surface_index[v] < 0) {
        surface_index[v] = int(m.vertices.size());
        m.vertices.push_back({st.vertices[3 * v], st.vertices[3 * v + 1], st.vertices[3 * v + 2]});
      }
      t[k] = std::uint32_t(surface_index[v]);
    }
    m.triangles.push_back(t);
    m.face_labels.push_back(labels[f]);
  }
  m.roles = meshes::sample_roles(true);
  st.removed_volume.assign(labels.size(), 0.0);
  st.wear_depth.assign(labels.size(), 0.0);
  return s;
}

void write_worn_stage(const std::string& path, const fem::WornSampleState& state,
                      const std::vector<double>& removed_volume) {
  const auto& m = state.surface;
  if (removed_volume.size() != m.n_faces())
    throw std::runtime_error("worn stage file '" + path +
                             "': " + std::to_string(removed_volume.size()) +
                             " removed volumes for " + std::to_string(m.n_faces()) + " faces");
  std::map<std::array<double, 3>, int> volume_vertex;
  for (std::size_t v = 0; 3 * v < state.vertices.size(); ++v)
    volume_vertex.emplace(std::array<double, 3>{state.vertices[3 * v], state.vertices[3 * v + 1],
                                                state.vertices[3 * v + 2]},
                          int(v));
  std::vector<int> to_volume(m.n_vertices());
  for (std::size_t v = 0; v < m.n_vertices(); ++v) {
    const auto it = volume_vertex.find({m.vertices[v].x, m.vertices[v].y, m.vertices[v].z});
    if (it == volume_vertex.end())
      throw std::runtime_error("worn stage file '" + path + "': surface vertex " +
                               std::to_string(v) + " is not a vertex of the volume mesh");
    to_volume[v] = it->second;
  }
  std::vector<int> triangles;
  triangles.reserve(3 * m.n_faces());
  for (const auto& t : m.triangles)
    for (const auto v : t)
      triangles.push_back(to_volume[v]);
  Hdf5File h5(path);
  h5.write("vertices", state.vertices, {state.vertices.size() / 3, 3});
  h5.write("tetrahedra", state.tetrahedra, {state.tetrahedra.size() / 4, 4});
  h5.write("triangles", triangles, {m.n_faces(), 3});
  h5.write("labels", m.face_labels, {m.n_faces()});
  h5.write("removed_volume", removed_volume, {m.n_faces()});
  h5.commit();
}

} // namespace wear::coupling
