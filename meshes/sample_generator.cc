// Parametric wear samples with gmsh's OpenCASCADE kernel.
//
// Geometry: a box (width x length x thickness) fused with half-ellipsoids (a unit sphere
// dilated by the footprint semi-axes and the height, intersected with the half-space above
// the base top face). Surfaces of the fused solid are labelled geometrically: z = 0 is the
// clamped bottom, planes at the box extent are sides, the plane z = thickness is the base
// top, and every other surface belongs to the element whose centre is nearest its centre
// of mass. Mesh size: a MathEval field grows linearly from `mesh_size` at the base top
// face to `mesh_size_bottom` at z = 0; curvature refinement resolves the element tips.
// Exact areas and volume come from OpenCASCADE (occ::getMass) for the accuracy checks.
#include "meshes/sample_generator.h"

#include "meshes/gmsh_session.h"

#include <gmsh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <unistd.h>
#include <unordered_map>

namespace wear::meshes {

namespace {
constexpr double pi = 3.14159265358979323846;
}

std::vector<ElementSite> element_sites(const SampleGeometry& s) {
  std::vector<ElementSite> sites;
  if (!s.convex)
    return sites;
  const auto& p = s.pattern;
  const double semi_flow = p.major_along_flow ? p.a : p.b;
  const double semi_radial = p.major_along_flow ? p.b : p.a;
  for (int j = 1; j <= p.n_columns; ++j) {
    const bool offset = p.stagger && j % 2 == 0;
    const int n = offset ? p.elements_per_column - 1 : p.elements_per_column;
    const double y = -s.length / 2 + p.first_column_offset + (j - 1) * p.d / 2;
    for (int k = 1; k <= n; ++k)
      sites.push_back({j, k, (k - (n + 1) / 2.0) * p.c, y, semi_radial, semi_flow});
  }
  return sites;
}

int set_sample_size_field(const SampleGeometry& s) {
  const double t = s.thickness;
  const int field = gmsh::model::mesh::field::add("MathEval");
  char expr[256];
  std::snprintf(expr, sizeof(expr), "%.17g + %.17g * (Fabs(%.17g - z) + (%.17g - z))", s.mesh_size,
                (s.mesh_size_bottom - s.mesh_size) / (2 * t), t, t);
  gmsh::model::mesh::field::setString(field, "F", expr);
  gmsh::model::mesh::field::setAsBackgroundMesh(field);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", s.curvature_refinement ? 16 : 0);
  gmsh::option::setNumber("Mesh.MeshSizeMin", s.mesh_size / 4);
  gmsh::option::setNumber("Mesh.MeshSizeMax", s.mesh_size_bottom);
  gmsh::option::setNumber("Mesh.Algorithm", 6);   // Frontal-Delaunay surfaces
  gmsh::option::setNumber("Mesh.Algorithm3D", 1); // Delaunay: HXT spent minutes optimising here
  return field;
}

GeneratedSample generate_sample(const SampleGeometry& s, const std::string& msh_path) {
  validate(s);
  const auto start = std::chrono::steady_clock::now();
  GmshSession session("sample");
  namespace occ = gmsh::model::occ;
  const double W = s.width, L = s.length, t = s.thickness;
  const int box = occ::addBox(-W / 2, -L / 2, 0, W, L, t);
  const auto sites = element_sites(s);
  gmsh::vectorpair solid{{3, box}}, out;
  std::vector<gmsh::vectorpair> out_map;
  if (!sites.empty()) {
    gmsh::vectorpair ellipsoids;
    for (const auto& e : sites) {
      const int sph = occ::addSphere(e.x, e.y, t, 1.0);
      occ::dilate({{3, sph}}, e.x, e.y, t, e.semi_x, e.semi_y, s.pattern.h);
      ellipsoids.push_back({3, sph});
    }
    const int upper = occ::addBox(-W, -L, t, 2 * W, 2 * L, 2 * s.pattern.h);
    gmsh::vectorpair halves;
    occ::intersect(ellipsoids, {{3, upper}}, halves, out_map);
    occ::fuse({{3, box}}, halves, out, out_map);
    solid = out;
  }
  occ::synchronize();
  if (solid.size() != 1)
    throw std::runtime_error("sample geometry: the boolean fusion gave " +
                             std::to_string(solid.size()) + " solids instead of one");
  GeneratedSample g;
  occ::getMass(3, solid[0].second, g.exact_volume);

  // Label every surface of the solid.
  const double eps = 1e-5 * std::max({W, L, t}); // OCC boxes carry a tolerance margin
  std::map<int, std::vector<int>> by_label;
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  for (const auto& [dim, tag] : surfaces) {
    // Planar faces are the box's: classified by position. Bounding boxes are not used for
    // this: OpenCASCADE pads them, and loosely so around the B-spline element footprints.
    std::string type;
    gmsh::model::getType(dim, tag, type);
    double cx, cy, cz;
    occ::getCenterOfMass(dim, tag, cx, cy, cz);
    int id = label::unlabelled;
    if (type == "Plane") {
      if (std::abs(cz) < eps)
        id = label::bottom;
      else if (std::abs(cz - t) < eps)
        id = label::base;
      else
        id = label::side;
    } else {
      double best = std::numeric_limits<double>::infinity();
      for (const auto& e : sites) {
        const double d2 = (cx - e.x) * (cx - e.x) + (cy - e.y) * (cy - e.y);
        if (d2 < best) {
          best = d2;
          id = label::convex_element(e.column, e.element);
        }
      }
    }
    if (id == label::unlabelled)
      throw std::runtime_error("sample geometry: surface " + std::to_string(tag) + " (" + type +
                               ") could not be labelled");
    by_label[id].push_back(tag);
    double area = 0;
    occ::getMass(dim, tag, area);
    g.exact_area[id] += area;
  }
  for (const auto& [id, tags] : by_label) {
    gmsh::model::addPhysicalGroup(2, tags, id);
    gmsh::model::setPhysicalName(2, id, label::name(id));
  }
  gmsh::model::addPhysicalGroup(3, {solid[0].second}, 1);
  gmsh::model::setPhysicalName(3, 1, "sample");

  set_sample_size_field(s);
  gmsh::model::mesh::generate(s.volume_mesh ? 3 : 2);
  if (!msh_path.empty())
    gmsh_write_msh(msh_path);
  g.surface = gmsh_labelled_surface(&g.n_tetrahedra, &g.tetrahedral_volume);
  g.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return g;
}

SurfaceMesh read_msh_surface(const std::string& path, std::size_t* n_tets, double* tet_volume) {
  if (!std::filesystem::exists(path))
    throw std::runtime_error("mesh file '" + path + "' does not exist");
  GmshSession session("read");
  try {
    gmsh::open(path);
  } catch (const std::exception& e) {
    throw std::runtime_error("mesh file '" + path + "' cannot be read by gmsh: " + e.what());
  }
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  if (groups.empty())
    throw std::runtime_error("mesh file '" + path +
                             "' has no surface physical groups (labels); regenerate it "
                             "with 'wearsim mesh'");
  auto m = gmsh_labelled_surface(n_tets, tet_volume);
  m.validate("mesh file '" + path + "'");
  return m;
}

Vec3 sample_to_tester(const Vec3& p, const SampleGeometry& s, const SamplePlacement& pl) {
  // Incline: rotate about the radial (x) axis through the wear-face centre; a positive
  // angle raises the trailing (+y) edge, so the leading edge is lower.
  const double th = pl.incline_deg * pi / 180;
  const Vec3 q{p.x, p.y, p.z - s.thickness};
  const Vec3 r{q.x, q.y * std::cos(th) - q.z * std::sin(th),
               q.y * std::sin(th) + q.z * std::cos(th)};
  // Sample x -> radial, y -> tangential (direction of the bed motion), z -> up.
  const double phi = pl.angle_deg * pi / 180;
  const double rad = pl.radius + r.x;
  return {rad * std::cos(phi) - r.y * std::sin(phi), rad * std::sin(phi) + r.y * std::cos(phi),
          pl.wear_face_height + r.z};
}

Vec3 tester_to_sample(const Vec3& p, const SampleGeometry& s, const SamplePlacement& pl) {
  const double phi = pl.angle_deg * pi / 180, th = pl.incline_deg * pi / 180;
  const double rad = p.x * std::cos(phi) + p.y * std::sin(phi);
  const Vec3 r{rad - pl.radius, -p.x * std::sin(phi) + p.y * std::cos(phi),
               p.z - pl.wear_face_height};
  return {r.x, r.y * std::cos(th) + r.z * std::sin(th),
          -r.y * std::sin(th) + r.z * std::cos(th) + s.thickness};
}

SurfaceMesh place_in_tester(const SurfaceMesh& m, const SampleGeometry& s,
                            const SamplePlacement& pl) {
  SurfaceMesh out = m;
  for (auto& v : out.vertices)
    v = sample_to_tester(v, s, pl);
  out.bump_revision();
  return out;
}

} // namespace wear::meshes
