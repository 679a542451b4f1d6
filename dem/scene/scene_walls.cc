// The scene's walls (scene_walls.h): each wall's surface from its file or primitive
// (meshes/cad_import.h), then the checks that need the geometry.
//
// A wearing wall must be a closed solid: its volume is what the FEM part meshes and wears
// (no boundary or non-manifold edge, check_closed). Every wall must lie inside Scene/Domain:
// a file drawn in millimetres and read as metres is 1000 times too large; the reader checks
// it (CadImportOptions::bounds, before meshing a CAD file) and the message names the wall,
// its file and its unit. A wearing wall's CAD surfaces take their roles (wearing, free,
// clamped, held) in the mesh's roles table, and labels named after number and role
// (meshes::label::part_surface).
//
// The tester's sample and holder (Source = sample, holder) are built by the tester's own
// generators (meshes::generate_sample, meshes::generate_holder) and placed by the tester's map
// (meshes::SampleFrame), so a scene that names them holds the same triangles as the built-in
// tester. The sample keeps its labels and their roles (meshes::sample_roles); with
// both walls present, the sample's sides and bottom and the holder's pocket coincide and are
// named covered, as in the tester (MeshWall: one contact where wear face and rim meet).
//
// A disc, an open cylinder or an open cone that does not wear and keeps its place
// (revolution_surface) is an exact surface of revolution in the engine (RevolutionWall), as
// the tester's floor and cylinders are, its loads summed as totals (it has one label); its
// triangles stay the wall's surface for the fill's checks and the output. They are chords of the
// exact surface, inside it by at most their sagitta (h^2 / 8 R for edges h on a circle of radius
// R).
#include "dem/scene/scene_walls.h"

#include "meshes/sample_frame.h"
#include "meshes/sample_generator.h"
#include "meshes/tester_walls.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <tuple>

namespace wear::dem {

namespace {

/// The labels present in `mesh`, ascending, with their areas.
void collect_labels(meshes::CadSurface& c) {
  std::map<int, double> area;
  const auto& m = c.mesh;
  const std::vector<double> face = meshes::face_areas(m);
  for (std::size_t f = 0; f < m.n_faces(); ++f)
    area[m.face_labels[f]] += face[f];
  for (const auto& [label, a] : area) {
    c.surface_labels.push_back(label);
    c.surface_areas.push_back(a);
  }
}

/// The tester's sample or holder where the tester places them; throws naming the wall when a
/// vertex lies outside the domain.
meshes::CadSurface tester_part(const SceneWallParameters& w,
                               const meshes::GeometryParameters& geometry,
                               const meshes::BoundingBox& domain) {
  const std::string what = scene_wall_path(w) + " (" + w.source + ")";
  meshes::SampleGeometry sample = geometry.sample;
  sample.volume_mesh = false;
  try {
    meshes::validate(geometry);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(what + ": " + e.what());
  }
  const meshes::SampleFrame frame(sample, geometry.placement);
  meshes::CadSurface c;
  if (wall_source_of(w).source == WallSource::sample) {
    const auto g = meshes::generate_sample(sample);
    c.mesh = frame.place_in_tester(g.surface);
    c.n_solids = 1;
    c.solid_volume = g.exact_volume;
    collect_labels(c);
    for (std::size_t k = 0; k < c.surface_labels.size(); ++k) // OpenCASCADE's exact areas
      c.surface_areas[k] = g.exact_area.at(c.surface_labels[k]);
  } else {
    meshes::TesterGeometry t = geometry.tester;
    t.wall_mesh_size = w.mesh_size;
    c.mesh = frame.place_in_tester(meshes::generate_holder(sample, t));
    collect_labels(c); // planar: the triangles' areas are exact
  }
  for (const auto& v : c.mesh.vertices)
    for (int d = 0; d < 3; ++d)
      if (v[d] < domain.min[d] || v[d] > domain.max[d])
        throw std::invalid_argument(what + ": the vertex (" + std::to_string(v.x) + ", " +
                                    std::to_string(v.y) + ", " + std::to_string(v.z) +
                                    ") m lies outside Scene/Domain (Geometry/Placement puts "
                                    "the sample there)");
  return c;
}

/// The mesh primitive of a primitive source.
meshes::PrimitiveKind primitive_kind(WallSource source) {
  switch (source) {
  case WallSource::plane:
    return meshes::PrimitiveKind::plane;
  case WallSource::disc:
    return meshes::PrimitiveKind::disc;
  case WallSource::cylinder:
    return meshes::PrimitiveKind::cylinder;
  case WallSource::cone:
    return meshes::PrimitiveKind::cone;
  case WallSource::box:
    return meshes::PrimitiveKind::box;
  default:
    throw std::logic_error("primitive_kind: not a primitive source");
  }
}

meshes::CadSurface surface_of(const SceneWallParameters& w, const meshes::BoundingBox& domain,
                              const meshes::GeometryParameters& geometry) {
  const std::string what = scene_wall_path(w);
  const WallSourceEntry& source = wall_source_of(w);
  if (source.tester_part)
    return tester_part(w, geometry, domain);
  if (source.source == WallSource::file) {
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
  p.kind = primitive_kind(source.source);
  p.origin = scene_vector(w.origin);
  p.edge_u = scene_vector(w.edge_u);
  p.edge_v = scene_vector(w.edge_v);
  p.axis = scene_vector(w.axis);
  p.radius = w.radius;
  p.radius_top = w.radius_top;
  p.radius_inner = w.radius_inner;
  p.caps = w.caps;
  return meshes::primitive_surface(p, w.mesh_size, what + " (" + w.source + ")", domain);
}

/// The wearing part's labels and their roles: each CAD surface n becomes S<n> (wearing),
/// S<n>-free, S<n>-clamped or S<n>-held (meshes::label::part_surface) as the wall's lists
/// say, its role set in the mesh's roles.
void label_part_surfaces(SceneWall& wall, const std::string& what) {
  const auto& w = wall.parameters;
  auto& surface = wall.surface;
  const auto clamped = surface_numbers(w.clamped_surfaces, what + "/Clamped surfaces");
  const auto held = surface_numbers(w.held_surfaces, what + "/Held surfaces");
  const bool all = w.wearing_surfaces == "all";
  const auto wearing =
      all ? std::vector<int>{} : surface_numbers(w.wearing_surfaces, what + "/Wearing surfaces");
  const auto& present = surface.surface_labels;
  const auto has = [](const std::vector<int>& list, int n) {
    return std::find(list.begin(), list.end(), n) != list.end();
  };
  std::string numbers;
  for (int n : present)
    numbers += (numbers.empty() ? "" : ", ") + std::to_string(n);
  for (const auto& [list, name] : {std::pair{&clamped, "Clamped surfaces"},
                                   {&wearing, "Wearing surfaces"},
                                   {&held, "Held surfaces"}})
    for (int n : *list)
      if (!has(present, n))
        throw std::invalid_argument(what + "/" + name + ": the part has no surface " +
                                    std::to_string(n) + " (its surfaces: " + numbers + ")");
  for (const auto& [a, b, names] : {std::tuple{&wearing, &clamped, "wearing and as clamped"},
                                    {&wearing, &held, "wearing and as held"},
                                    {&clamped, &held, "clamped and as held"}})
    for (int n : *a)
      if (has(*b, n))
        throw std::invalid_argument(what + ": surface " + std::to_string(n) +
                                    " is listed both as " + names);
  for (int n : present)
    if (n < 1 || n > meshes::label::max_part_surfaces)
      throw std::invalid_argument(what + ": a wearing part's surfaces must be numbered 1 ... " +
                                  std::to_string(meshes::label::max_part_surfaces) +
                                  ", the file has label " + std::to_string(n));
  std::map<int, int> label_of;
  for (int n : present) {
    using meshes::FaceRole;
    const FaceRole role = has(clamped, n)          ? FaceRole::clamped
                          : has(held, n)           ? FaceRole::held
                          : all || has(wearing, n) ? FaceRole::wearing
                                                   : FaceRole::free;
    label_of[n] = meshes::label::part_surface(role, n);
    surface.mesh.roles.set(label_of[n], role);
  }
  for (auto& l : surface.mesh.face_labels)
    l = label_of.at(l);
  for (auto& l : surface.surface_labels)
    l = label_of.at(l);
}

} // namespace

std::vector<SceneWall> build_scene_walls(const SceneParameters& scene,
                                         const meshes::GeometryParameters& geometry) {
  validate(scene);
  const meshes::Vec3 lo = scene_vector(scene.domain_min), hi = scene_vector(scene.domain_max);
  const bool held =
      std::any_of(scene.walls.begin(), scene.walls.end(), [](const SceneWallParameters& w) {
        return wall_source_of(w).source == WallSource::holder;
      });
  std::vector<SceneWall> walls;
  for (const auto& w : scene.walls) {
    SceneWall wall{w, surface_of(w, {lo, hi}, geometry), {}};
    const WallSource source = wall_source_of(w).source;
    if (held && source == WallSource::sample)
      wall.covered_labels = {meshes::label::side, meshes::label::bottom};
    if (source == WallSource::holder)
      wall.covered_labels = {meshes::label::pocket};
    const std::string what =
        scene_wall_path(w) +
        (source == WallSource::file ? " ('" + w.file + "', unit " + w.unit + ")" : "");
    if (w.wears) {
      const auto report = meshes::check_closed(wall.surface.mesh);
      if (!report.closed())
        throw std::invalid_argument(
            what + ": a wearing wall must be a closed solid; its surface has " +
            std::to_string(report.n_boundary_edges) + " boundary and " +
            std::to_string(report.n_nonmanifold_edges) + " non-manifold edges");
      if (source != WallSource::sample) // the sample's labels carry their roles already
        label_part_surfaces(wall, scene_wall_path(w));
    }
    walls.push_back(std::move(wall));
  }
  return walls;
}

std::optional<RevolutionSurface> revolution_surface(const SceneWallParameters& w) {
  if (!w.exact || w.wears || moves_rigidly(w))
    return std::nullopt;
  RevolutionSurface s;
  const Vec3 axis = scene_vector(w.axis);
  s.axis_point = scene_vector(w.origin);
  s.axis = meshes::normalized(axis);
  const WallSource source = wall_source_of(w).source;
  if (source == WallSource::disc) {
    s.kind = RevolutionKind::annulus;
    s.height = 0;
    s.inner_radius = w.radius_inner;
    s.outer_radius = w.radius;
    return s;
  }
  if (wall_source_of(w).revolution && !w.caps) { // a cylinder or a cone
    const bool cone = source == WallSource::cone;
    s.kind = cone ? RevolutionKind::cone : RevolutionKind::cylinder;
    s.radius = w.radius;
    s.radius_top = cone ? w.radius_top : w.radius;
    s.axial_min = 0;
    s.axial_max = meshes::norm(axis);
    return s;
  }
  return std::nullopt;
}

} // namespace wear::dem
