// gmsh session guard, and reading and writing the current gmsh model. gmsh keeps global
// state, so nesting sessions is refused rather than silently sharing one model.
#include "meshes/gmsh_session.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <unistd.h>
#include <unordered_map>

namespace wear::meshes {

namespace {
std::mutex gmsh_mutex;
bool active = false;
} // namespace

GmshSession::GmshSession(const std::string& model_name) {
  std::lock_guard<std::mutex> lock(gmsh_mutex);
  if (active)
    throw std::logic_error("a gmsh session is already open; gmsh has one global model");
  gmsh::initialize(0, nullptr, false);
  const char* verbose = std::getenv("WEAR_GMSH_VERBOSE");
  gmsh::option::setNumber("General.Terminal", verbose && verbose[0] == '1' ? 1 : 0);
  gmsh::option::setNumber("General.Verbosity", verbose && verbose[0] == '1' ? 5 : 1);
  gmsh::model::add(model_name);
  active = true;
}

GmshSession::~GmshSession() {
  std::lock_guard<std::mutex> lock(gmsh_mutex);
  gmsh::finalize();
  active = false;
}

SurfaceMesh gmsh_labelled_surface(std::size_t* n_tets, double* tet_volume, double* min_quality) {
  std::vector<std::size_t> node_tags;
  std::vector<double> coords, param;
  gmsh::model::mesh::getNodes(node_tags, coords, param, -1, -1, false, false);
  std::unordered_map<std::size_t, std::uint32_t> index;
  index.reserve(node_tags.size());
  SurfaceMesh m;
  m.vertices.reserve(node_tags.size());
  for (std::size_t i = 0; i < node_tags.size(); ++i) {
    index[node_tags[i]] = static_cast<std::uint32_t>(i);
    m.vertices.push_back({coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]});
  }
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  for (const auto& [dim, tag] : groups) {
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    for (int e : entities) {
      std::vector<std::size_t> elem, nodes;
      gmsh::model::mesh::getElementsByType(2, elem, nodes, e);
      for (std::size_t t = 0; t < elem.size(); ++t) {
        m.triangles.push_back(
            {index.at(nodes[3 * t]), index.at(nodes[3 * t + 1]), index.at(nodes[3 * t + 2])});
        m.face_labels.push_back(tag);
      }
    }
  }
  if (n_tets || tet_volume || min_quality) {
    std::vector<std::size_t> elem, nodes;
    gmsh::model::mesh::getElementsByType(4, elem, nodes, -1);
    double v = 0, smallest = 1;
    for (std::size_t t = 0; t < elem.size(); ++t) {
      Vec3 x[4];
      for (int k = 0; k < 4; ++k)
        x[k] = m.vertices[index.at(nodes[4 * t + k])];
      const double six_v = std::abs(dot(x[1] - x[0], cross(x[2] - x[0], x[3] - x[0])));
      v += six_v / 6.0;
      if (min_quality) {
        double l_max = 0;
        for (int i = 0; i < 4; ++i)
          for (int j = i + 1; j < 4; ++j)
            l_max = std::max(l_max, norm(x[j] - x[i]));
        smallest = std::min(smallest, std::sqrt(2.0) * six_v / (l_max * l_max * l_max));
      }
    }
    if (n_tets)
      *n_tets = elem.size();
    if (tet_volume)
      *tet_volume = v;
    if (min_quality)
      *min_quality = smallest;
  }
  // Keep only the vertices the surface uses, so the mesh is self-contained.
  SurfaceMesh compact;
  compact.triangles = m.triangles;
  compact.face_labels = m.face_labels;
  compact.vertices = m.vertices;
  {
    std::vector<std::int64_t> remap(m.vertices.size(), -1);
    std::vector<Vec3> used;
    for (auto& t : compact.triangles)
      for (auto& v : t) {
        if (remap[v] < 0) {
          remap[v] = static_cast<std::int64_t>(used.size());
          used.push_back(m.vertices[v]);
        }
        v = static_cast<std::uint32_t>(remap[v]);
      }
    compact.vertices = std::move(used);
  }
  orient_outward(compact);
  compact.set_revision(1);
  return compact;
}

void gmsh_write_msh(const std::string& path) {
  // gmsh picks the format from the extension, so the temporary name keeps ".msh".
  const std::string tmp = path + ".tmp." + std::to_string(::getpid()) + ".msh";
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::option::setNumber("Mesh.Binary", 0);
  gmsh::write(tmp);
  if (!std::filesystem::exists(tmp))
    throw std::runtime_error("cannot write mesh file '" + path + "'");
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot rename the temporary mesh onto '" + path + "'");
  }
}

} // namespace wear::meshes
