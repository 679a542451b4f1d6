// Reading the user's CAD and mesh files into labelled triangle surfaces (cad_import.h).
//
// CAD (STEP, IGES, BREP): gmsh's OpenCASCADE kernel imports the shapes, scales them by the
// file's unit about the origin (x_m = s x_file, s = 1 or 1e-3), then meshes the surfaces with
// Frontal-Delaunay at the target size (Mesh.MeshSizeMin = size / 4 where curvature asks,
// MeshSizeMax = size, 20 elements per 2 pi of curvature). Each CAD surface becomes a physical
// group whose tag is the surface's tag, so the triangles carry it as their label; surfaces
// shared by two solids are meshed once (gmsh's conformal mesh), and a solid's boundary comes
// out closed and outward. The exact areas and volumes come from the kernel, so a caller can
// judge the triangles against them (the chord error of a curved face, about (h/R)^2 / 12 of
// its area for edges h on radius R).
//
// Primitives (plane, disc, cylinder, cone, box) are built in the same kernel and meshed by
// the same path: a disc is made in the xy plane and turned from +z onto its normal; a
// cylinder or cone without caps keeps its side only (its planar faces removed).
//
// Checked facts (Debian 12, gmsh 4.8.4, OpenCASCADE 7.6): the STEP reader prints coloured
// banners on stdout whatever General.Terminal says, so stdout is pointed at /dev/null while it
// reads and the banners do not mix into a run's log; gmsh imports neither ADVANCED_FACE names
// nor other face names of a STEP file (only the product name, as the solid's entity name
// 'Shapes/<product>'), and its STEP writer writes no names: surfaces are named by index.
#include "meshes/cad_import.h"

#include "meshes/constants.h"
#include "meshes/gmsh_session.h"
#include "meshes/stl_io.h"

#include <gmsh.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace wear::meshes {

LengthUnit parse_length_unit(const std::string& text, const std::string& what) {
  if (text == "m")
    return LengthUnit::metre;
  if (text == "mm")
    return LengthUnit::millimetre;
  throw std::invalid_argument(what + ": unknown length unit '" + text + "' (m or mm)");
}

double metres_per(LengthUnit unit) {
  return unit == LengthUnit::millimetre ? 1e-3 : 1.0;
}

namespace {

std::string lower_extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

/// stdout pointed at /dev/null for the lifetime of the guard (OpenCASCADE's banners).
class QuietStdout {
public:
  QuietStdout() {
    std::fflush(stdout);
    saved_ = ::dup(STDOUT_FILENO);
    const int null = ::open("/dev/null", O_WRONLY);
    if (saved_ >= 0 && null >= 0)
      ::dup2(null, STDOUT_FILENO);
    if (null >= 0)
      ::close(null);
  }
  ~QuietStdout() {
    std::fflush(stdout);
    if (saved_ >= 0) {
      ::dup2(saved_, STDOUT_FILENO);
      ::close(saved_);
    }
  }
  QuietStdout(const QuietStdout&) = delete;
  QuietStdout& operator=(const QuietStdout&) = delete;

private:
  int saved_ = -1;
};

/// Throws std::invalid_argument when `extent` reaches outside `bounds`, naming both: the
/// usual sign of a file read in the wrong unit.
void require_inside(const BoundingBox& extent, const BoundingBox& bounds, const std::string& what) {
  const Vec3 &a = extent.min, &b = extent.max, &lo = bounds.min, &hi = bounds.max;
  if (a.x >= lo.x && a.y >= lo.y && a.z >= lo.z && b.x <= hi.x && b.y <= hi.y && b.z <= hi.z)
    return;
  char text[512];
  std::snprintf(text, sizeof text,
                " spans (%.4g, %.4g, %.4g) to (%.4g, %.4g, %.4g) m, outside the domain "
                "(%.4g, %.4g, %.4g) to (%.4g, %.4g, %.4g) m; is the unit right?",
                a.x, a.y, a.z, b.x, b.y, b.z, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
  throw std::invalid_argument(what + text);
}

CadSurface read_stl_surface(const std::string& path, double scale) {
  CadSurface out;
  out.mesh = read_stl(path);
  for (auto& v : out.mesh.vertices)
    v = scale * v;
  out.mesh.set_revision(1);
  for (const auto& [label, area] : area_per_label(out.mesh)) {
    out.surface_labels.push_back(label);
    out.surface_areas.push_back(area);
  }
  return out;
}

/// The current gmsh model's surfaces meshed at `mesh_size`, one physical group (= label) per
/// surface, with the kernel's areas and volumes; `what` names the source in errors.
CadSurface mesh_model(const std::string& what, double mesh_size,
                      const std::optional<BoundingBox>& bounds) {
  gmsh::vectorpair surfaces, solids;
  gmsh::model::getEntities(surfaces, 2);
  gmsh::model::getEntities(solids, 3);
  if (surfaces.empty())
    throw std::runtime_error(what + " holds no surface");
  if (bounds) {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
    require_inside({{x0, y0, z0}, {x1, y1, z1}}, *bounds, what);
  }
  CadSurface out;
  std::sort(surfaces.begin(), surfaces.end());
  for (const auto& [dim, tag] : surfaces) {
    gmsh::model::addPhysicalGroup(2, {tag}, tag);
    double area = 0;
    gmsh::model::occ::getMass(2, tag, area);
    out.surface_labels.push_back(tag);
    out.surface_areas.push_back(area);
  }
  for (const auto& [dim, tag] : solids) {
    double volume = 0;
    gmsh::model::occ::getMass(3, tag, volume);
    out.solid_volume += volume;
  }
  out.n_solids = solids.size();
  double total = 0;
  for (const double a : out.surface_areas)
    total += a;
  const double estimate = total / (std::sqrt(3.0) / 4 * mesh_size * mesh_size);
  if (estimate > max_cad_triangles) {
    char text[256];
    std::snprintf(text, sizeof text,
                  ": %.4g m^2 at %.4g m would make about %.3g triangles (at most %.3g); a "
                  "larger mesh size, or is the unit right?",
                  total, mesh_size, estimate, max_cad_triangles);
    throw std::invalid_argument(what + text);
  }
  gmsh::option::setNumber("Mesh.MeshSizeMin", mesh_size / 4);
  gmsh::option::setNumber("Mesh.MeshSizeMax", mesh_size);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 20);
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  try {
    gmsh::model::mesh::generate(2);
  } catch (const std::string& e) { // the gmsh API throws its last error as a string
    throw std::runtime_error(what + ": gmsh could not mesh its surfaces at " +
                             std::to_string(mesh_size) + " m (" + e + ")");
  }
  out.mesh = gmsh_labelled_surface();
  if (out.mesh.n_faces() == 0)
    throw std::runtime_error(what + ": meshing gave no triangle");
  return out;
}

CadSurface read_cad(const std::string& path, double scale, double mesh_size,
                    const std::optional<BoundingBox>& bounds) {
  GmshSession session("cad");
  gmsh::vectorpair imported;
  try {
    const QuietStdout quiet;
    gmsh::model::occ::importShapes(path, imported);
  } catch (const std::string& e) {
    throw std::runtime_error("CAD file '" + path + "': OpenCASCADE cannot read it (" + e + ")");
  }
  gmsh::vectorpair all;
  gmsh::model::occ::getEntities(all, -1);
  if (scale != 1)
    gmsh::model::occ::dilate(all, 0, 0, 0, scale, scale, scale);
  gmsh::model::occ::synchronize();
  return mesh_model("CAD file '" + path + "'", mesh_size, bounds);
}

/// Rotates the entities from +z onto the direction n (unit), about the point c.
void rotate_from_z(const gmsh::vectorpair& e, const Vec3& c, const Vec3& n) {
  const Vec3 z{0, 0, 1};
  const Vec3 k = cross(z, n);
  const double s = norm(k), co = dot(z, n);
  if (s < 1e-14) {
    if (co < 0)
      gmsh::model::occ::rotate(e, c.x, c.y, c.z, 1, 0, 0, wear::pi);
    return;
  }
  gmsh::model::occ::rotate(e, c.x, c.y, c.z, k.x, k.y, k.z, std::atan2(s, co));
}

void require_positive(double v, const std::string& what, const std::string& name) {
  if (!(v > 0) || !std::isfinite(v))
    throw std::invalid_argument(what + ": " + name + " must be positive [m], got " +
                                std::to_string(v));
}

} // namespace

CadSurface primitive_surface(const Primitive& p, double mesh_size, const std::string& what,
                             const std::optional<BoundingBox>& bounds) {
  require_positive(mesh_size, what, "the triangle size");
  GmshSession session("primitive");
  const Vec3& o = p.origin;
  switch (p.kind) {
  case PrimitiveKind::plane: {
    const double a = norm(p.edge_u), b = norm(p.edge_v);
    require_positive(a, what, "the first edge's length");
    require_positive(b, what, "the second edge's length");
    if (norm(cross(p.edge_u, p.edge_v)) < 1e-9 * a * b)
      throw std::invalid_argument(what + ": the plane's two edges are parallel");
    const Vec3 c[4] = {o, o + p.edge_u, o + p.edge_u + p.edge_v, o + p.edge_v};
    int pt[4], ln[4];
    for (int k = 0; k < 4; ++k)
      pt[k] = gmsh::model::occ::addPoint(c[k].x, c[k].y, c[k].z);
    for (int k = 0; k < 4; ++k)
      ln[k] = gmsh::model::occ::addLine(pt[k], pt[(k + 1) % 4]);
    const int loop = gmsh::model::occ::addCurveLoop({ln[0], ln[1], ln[2], ln[3]});
    gmsh::model::occ::addPlaneSurface({loop});
    break;
  }
  case PrimitiveKind::disc: {
    require_positive(p.radius, what, "the radius");
    require_positive(norm(p.axis), what, "the normal's length");
    if (p.radius_inner < 0 || p.radius_inner >= p.radius)
      throw std::invalid_argument(what + ": the hole's radius must lie in [0, radius), got " +
                                  std::to_string(p.radius_inner));
    int d = gmsh::model::occ::addDisk(o.x, o.y, o.z, p.radius, p.radius);
    if (p.radius_inner > 0) { // an annulus: a hopper's floor around its orifice
      const int hole = gmsh::model::occ::addDisk(o.x, o.y, o.z, p.radius_inner, p.radius_inner);
      gmsh::vectorpair out;
      std::vector<gmsh::vectorpair> map;
      gmsh::model::occ::cut({{2, d}}, {{2, hole}}, out, map);
      d = out.at(0).second;
    }
    rotate_from_z({{2, d}}, o, p.axis * (1 / norm(p.axis)));
    break;
  }
  case PrimitiveKind::cylinder:
  case PrimitiveKind::cone: {
    require_positive(p.radius, what, "the radius");
    require_positive(norm(p.axis), what, "the axis' length");
    const bool cone = p.kind == PrimitiveKind::cone;
    if (cone && (p.radius_top < 0 || p.radius_top == p.radius))
      throw std::invalid_argument(what +
                                  ": the cone's top radius must be >= 0 and differ from "
                                  "its base radius, got " +
                                  std::to_string(p.radius_top));
    const int v =
        cone ? gmsh::model::occ::addCone(o.x, o.y, o.z, p.axis.x, p.axis.y, p.axis.z, p.radius,
                                         p.radius_top)
             : gmsh::model::occ::addCylinder(o.x, o.y, o.z, p.axis.x, p.axis.y, p.axis.z, p.radius);
    if (!p.caps) { // keep the side only
      gmsh::vectorpair faces;
      gmsh::model::occ::synchronize();
      gmsh::model::getBoundary({{3, v}}, faces, false, false, false);
      gmsh::model::occ::remove({{3, v}});
      for (const auto& [dim, tag] : faces) {
        std::string type;
        gmsh::model::getType(2, std::abs(tag), type);
        if (type == "Plane")
          gmsh::model::occ::remove({{2, std::abs(tag)}}, true);
      }
    }
    break;
  }
  case PrimitiveKind::box:
    require_positive(p.axis.x, what, "the box's x size");
    require_positive(p.axis.y, what, "the box's y size");
    require_positive(p.axis.z, what, "the box's z size");
    gmsh::model::occ::addBox(o.x, o.y, o.z, p.axis.x, p.axis.y, p.axis.z);
    break;
  }
  gmsh::model::occ::synchronize();
  return mesh_model(what, mesh_size, bounds);
}

CadSurface read_cad_surface(const std::string& path, const CadImportOptions& options) {
  if (!std::filesystem::exists(path))
    throw std::runtime_error("CAD file '" + path + "' does not exist");
  if (!std::ifstream(path))
    throw std::runtime_error("CAD file '" + path + "' cannot be read");
  const double scale = metres_per(options.unit);
  const std::string ext = lower_extension(path);
  if (ext == ".stl") {
    CadSurface stl = read_stl_surface(path, scale);
    if (options.bounds)
      require_inside(bounding_box(stl.mesh), *options.bounds, "CAD file '" + path + "'");
    return stl;
  }
  if (ext != ".step" && ext != ".stp" && ext != ".iges" && ext != ".igs" && ext != ".brep")
    throw std::runtime_error("CAD file '" + path + "': unknown extension '" + ext +
                             "' (known: .step, .stp, .iges, .igs, .brep, .stl)");
  if (!(options.mesh_size > 0))
    throw std::invalid_argument("CAD file '" + path +
                                "': the triangle size must be positive [m], got " +
                                std::to_string(options.mesh_size));
  return read_cad(path, scale, options.mesh_size, options.bounds);
}

} // namespace wear::meshes
