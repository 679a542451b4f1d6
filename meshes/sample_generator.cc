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
#include "meshes/sample_frame.h"
#include "meshes/stopwatch.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <unistd.h>
#include <unordered_map>

namespace wear::meshes {

namespace {}

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

int set_sample_size_field(const SampleGeometry& s, const Vec3& up, double up_offset) {
  const double t = s.thickness;
  const int field = gmsh::model::mesh::field::add("MathEval");
  char height[160], expr[512];
  if (up.x == 0 && up.y == 0 && up.z == 1 && up_offset == 0)
    std::snprintf(height, sizeof(height), "z");
  else
    std::snprintf(height, sizeof(height), "(0%+.17g * x %+.17g * y %+.17g * z %+.17g)", up.x, up.y,
                  up.z, -up_offset); // explicit signs: MathEval reads no "- -"
  std::snprintf(expr, sizeof(expr), "%.17g + %.17g * (Fabs(%.17g - %s) + (%.17g - %s))",
                s.mesh_size, (s.mesh_size_bottom - s.mesh_size) / (2 * t), t, height, t, height);
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

GeneratedSample generate_sample(const SampleGeometry& s, const std::string& msh_path,
                                const SamplePlacement* placement) {
  validate(s);
  const Stopwatch clock;
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
  if (!sites.empty())
    g.exact_element_volume = g.exact_volume - W * L * t;

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
  if (placement) {
    const SampleFrame frame(s, *placement);
    std::vector<std::size_t> tags;
    std::vector<double> x, unused;
    gmsh::model::mesh::getNodes(tags, x, unused, -1, -1, false, false);
    for (std::size_t k = 0; k < tags.size(); ++k) {
      const Vec3 q = frame.point_to_tester({x[3 * k], x[3 * k + 1], x[3 * k + 2]});
      gmsh::model::mesh::setNode(tags[k], {q.x, q.y, q.z}, {});
    }
  }
  if (!msh_path.empty())
    gmsh_write_msh(msh_path);
  g.surface = gmsh_labelled_surface(&g.n_tetrahedra, &g.tetrahedral_volume);
  g.surface.roles = sample_roles(false);
  g.seconds = clock.seconds();
  return g;
}

ElementVolume element_volume(const GeneratedSample& g, const SampleGeometry& s) {
  ElementVolume v;
  v.exact = g.exact_element_volume;
  for (int id : g.surface.labels())
    if (label::is_convex_element(id))
      v.meshed += volume_above_plane(g.surface, id, s.thickness);
  return v;
}

std::string element_volume_warning(const ElementVolume& v, const SampleGeometry& s,
                                   double tolerance) {
  if (!(v.deficit() > tolerance))
    return "";
  char text[512];
  std::snprintf(text, sizeof text,
                "the meshed convex elements hold %.1f %% less volume than the CAD's (%.4g of "
                "%.4g mm^3 above the base top) at Geometry/Sample/Mesh size = %g m%s: their wear "
                "and life are off by about as much; set %sa smaller Mesh size",
                100 * v.deficit(), v.meshed * 1e9, v.exact * 1e9, s.mesh_size,
                s.curvature_refinement ? "" : " without Curvature refinement",
                s.curvature_refinement ? "" : "Curvature refinement = true or ");
  return text;
}

LabelRoles sample_roles(bool held_sides) {
  LabelRoles r;
  r.set(label::bottom, FaceRole::clamped);
  r.set(label::side, held_sides ? FaceRole::held : FaceRole::free);
  r.set(label::base, FaceRole::wearing);
  for (int column = 1; column <= 9; ++column)
    for (int element = 1; element <= 9; ++element)
      r.set(label::convex_element(column, element), FaceRole::wearing);
  return r;
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

} // namespace wear::meshes
