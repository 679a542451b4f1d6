// The scene's walls (scene_walls.h): each wall's surface from its file or primitive
// (meshes/cad_import.h), then the checks that need the geometry.
//
// A wearing wall must be a closed solid: its volume is what the FEM part meshes and wears
// (no boundary or non-manifold edge, check_closed). Every vertex must lie inside
// Scene/Domain: a file drawn in millimetres and read as metres is 1000 times too large, and
// this is where it shows, naming the wall's extent and its unit.
#include "dem/scene/scene_walls.h"

#include <sstream>
#include <stdexcept>

namespace wear::dem {

namespace {

std::string path_of(const SceneWallParameters& w) {
  return "Scene/Wall " + w.name;
}

meshes::Vec3 vec(const std::vector<double>& v) {
  return {v.at(0), v.at(1), v.at(2)};
}

std::string text(const meshes::Vec3& v) {
  std::ostringstream s;
  s.precision(4);
  s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return s.str();
}

meshes::CadSurface surface_of(const SceneWallParameters& w, const meshes::BoundingBox& domain) {
  const std::string what = path_of(w);
  if (w.source == "file") {
    meshes::CadImportOptions o{meshes::parse_length_unit(w.unit, what + "/Unit"), w.mesh_size,
                               domain};
    try {
      return meshes::read_cad_surface(w.file, o);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(what + " (File = " + w.file + ", Unit = " + w.unit +
                                  "): " + e.what());
    }
  }
  meshes::Primitive p;
  p.kind = w.source == "plane"      ? meshes::PrimitiveKind::plane
           : w.source == "disc"     ? meshes::PrimitiveKind::disc
           : w.source == "cylinder" ? meshes::PrimitiveKind::cylinder
           : w.source == "cone"     ? meshes::PrimitiveKind::cone
                                    : meshes::PrimitiveKind::box;
  p.origin = vec(w.origin);
  p.edge_u = vec(w.edge_u);
  p.edge_v = vec(w.edge_v);
  p.axis = vec(w.axis);
  p.radius = w.radius;
  p.radius_top = w.radius_top;
  p.caps = w.caps;
  return meshes::primitive_surface(p, w.mesh_size, what + " (" + w.source + ")", domain);
}

} // namespace

std::vector<SceneWall> build_scene_walls(const SceneParameters& scene) {
  validate(scene);
  const meshes::Vec3 lo = vec(scene.domain_min), hi = vec(scene.domain_max);
  std::vector<SceneWall> walls;
  for (const auto& w : scene.walls) {
    SceneWall wall{w, surface_of(w, {lo, hi})};
    const std::string what =
        path_of(w) + (w.source == "file" ? " ('" + w.file + "', unit " + w.unit + ")" : "");
    if (w.wears) {
      const auto report = meshes::check_closed(wall.surface.mesh);
      if (!report.closed())
        throw std::invalid_argument(
            what + ": a wearing wall must be a closed solid; its surface has " +
            std::to_string(report.n_boundary_edges) + " boundary and " +
            std::to_string(report.n_nonmanifold_edges) + " non-manifold edges");
    }
    const auto box = meshes::bounding_box(wall.surface.mesh);
    if (box.min.x < lo.x || box.min.y < lo.y || box.min.z < lo.z || box.max.x > hi.x ||
        box.max.y > hi.y || box.max.z > hi.z)
      throw std::invalid_argument(what + " spans " + text(box.min) + " to " + text(box.max) +
                                  " m, outside Scene/Domain " + text(lo) + " to " + text(hi) +
                                  " m; is the unit right?");
    walls.push_back(std::move(wall));
  }
  return walls;
}

} // namespace wear::dem
