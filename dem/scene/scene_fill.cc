// Where a scene's fill places particles (scene_fill.h).
//
// The fill region is checked against every wall triangle (a box by separating axes, a cylinder
// by clipping the triangle to its slab; both exact) before any particle exists: particles
// placed through a wall would start overlapping it. A wall wholly inside the region is
// submerged (a part standing in the bed, as the tester's sample and its holder): no centre is
// placed inside its solid or within the largest diameter of its surface (closed; its bounding
// box, turned with the part, would keep a larger bed clear than the part takes), or within
// that diameter of its bounding box (open), and a bed height's count leaves out its enclosed
// volume below the bed's top (the share of its height below it, when it reaches above).
#include "dem/scene/scene_fill.h"

#include "dem/scene/wall_catalogue.h"
#include "meshes/cad_import.h"
#include "meshes/constants.h"
#include "meshes/triangle_geometry.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

namespace wear::dem {

namespace {

Vec3 vec(const std::vector<double>& v) {
  return scene_vector(v);
}

} // namespace

std::string SceneFillShape::describe() const {
  std::ostringstream s;
  if (solid)
    s << "the solid of " << file;
  else if (cylinder)
    s << "the cylinder of radius " << radius << " m"
      << (radius_inner > 0 ? " (inner " + std::to_string(radius_inner) + " m)" : std::string())
      << " from (" << base.x << ", " << base.y << ", " << base.z << ") m, " << length << " m long";
  else
    s << "the box (" << lo.x << ", " << lo.y << ", " << lo.z << ") .. (" << hi.x << ", " << hi.y
      << ", " << hi.z << ") m";
  return s.str();
}

bool SceneFillShape::cuts(const Vec3& a, const Vec3& b, const Vec3& c) const {
  if (solid)
    return solid->cuts(a, b, c);
  return cylinder ? meshes::triangle_intersects_cylinder(a, b, c, base, axis, length, radius,
                                                         radius_inner)
                  : meshes::triangle_intersects_box(a, b, c, lo, hi);
}

FillRegion SceneFillShape::region(double margin, double z_top) const {
  FillRegion r = outline(margin, z_top);
  if (submerged.empty())
    return r;
  r.inside = [in = r.inside, walls = submerged, above = cleared_above,
              c = clearance](const Vec3& x) {
    const auto beside = [&](const meshes::BoundingBox& b) {
      return x.x > b.min.x - c && x.x < b.max.x + c && x.y > b.min.y - c && x.y < b.max.y + c;
    };
    for (const auto& w : walls)
      if (beside(w.box) && x.z > w.box.min.z - c && x.z < w.box.max.z + c &&
          (!w.solid || w.solid->distance(x) < c || w.solid->contains(x)))
        return false;
    for (const auto& b : above)
      if (beside(b) && x.z > b.min.z - c)
        return false;
    return in(x);
  };
  return r;
}

bool SceneFillShape::contains_all(const std::vector<Vec3>& points) const {
  const FillRegion r = outline(0, hi.z);
  return std::all_of(points.begin(), points.end(), [&](const Vec3& x) {
    return x.x >= r.lo.x && x.y >= r.lo.y && x.z >= r.lo.z && x.x <= r.hi.x && x.y <= r.hi.y &&
           x.z <= r.hi.z && r.inside(x);
  });
}

FillRegion SceneFillShape::outline(double margin, double z_top) const {
  if (solid) {
    FillRegion r{solid->box().min + Vec3{margin, margin, margin},
                 solid->box().max - Vec3{margin, margin, margin},
                 {}};
    r.hi.z = std::fmin(r.hi.z, z_top - margin);
    r.inside = [s = solid, margin](const Vec3& x) {
      return s->contains(x) && s->distance(x) >= margin;
    };
    return r;
  }
  if (!cylinder)
    return box_region(lo, {hi.x, hi.y, z_top}, margin);
  const double top = std::fmin(length, z_top - base.z);
  FillRegion r{lo + Vec3{margin, margin, margin}, hi - Vec3{margin, margin, margin}, {}};
  r.hi.z = std::fmin(r.hi.z, z_top - margin);
  r.inside = [b = base, u = axis, top, R = radius, r_in = radius_inner, a = sector,
              margin](const Vec3& x) {
    const Vec3 d = x - b;
    const double s = meshes::dot(d, u);
    const double rho = meshes::norm(d - u * s);
    const bool in_sector =
        a == 0 || (x.y >= margin && std::sin(a) * x.x - std::cos(a) * x.y >= margin);
    return s >= margin && s <= top - margin && rho <= R - margin &&
           (r_in == 0 || rho >= r_in + margin) && in_sector;
  };
  return r;
}

SceneFillShape fill_shape(const SceneParameters& s, double loose_factor) {
  const SceneFillParameters& f = s.fill;
  SceneFillShape shape;
  if (f.region == "mesh") {
    meshes::CadImportOptions o{
        meshes::parse_length_unit(f.unit, "Scene/Fill/Unit"), f.mesh_size, {}};
    shape.solid = std::make_shared<const meshes::SolidRegion>(
        meshes::read_cad_surface(f.file, o).mesh, "Scene/Fill (File = " + f.file + ")");
    shape.file = "'" + f.file + "'";
    shape.lo = shape.solid->box().min;
    shape.hi = shape.solid->box().max;
    shape.floor_z = shape.lo.z;
    shape.full_top = shape.hi.z;
    return shape;
  }
  if (f.region == "cylinder") {
    shape.cylinder = true;
    shape.base = vec(f.origin);
    const Vec3 a = vec(f.axis);
    shape.length = meshes::norm(a);
    shape.axis = a / shape.length;
    shape.radius = f.radius;
    for (int d = 0; d < 3; ++d) {
      const double e = f.radius * std::sqrt(std::fmax(0.0, 1 - shape.axis[d] * shape.axis[d]));
      shape.lo[d] = std::fmin(shape.base[d], shape.base[d] + a[d]) - e;
      shape.hi[d] = std::fmax(shape.base[d], shape.base[d] + a[d]) + e;
    }
    shape.floor_z = shape.base.z;
    if (fills_sector_only(s))
      shape.sector = s.periodic_angle_deg * pi / 180;
    shape.radius_inner = f.radius_inner;
    shape.footprint = pi * (f.radius * f.radius - f.radius_inner * f.radius_inner) *
                      (shape.sector > 0 ? shape.sector / (2 * pi) : 1.0);
  } else {
    shape.lo = vec(f.minimum);
    shape.hi = vec(f.maximum);
    shape.floor_z = shape.lo.z;
    shape.footprint = (shape.hi.x - shape.lo.x) * (shape.hi.y - shape.lo.y);
  }
  shape.full_top = shape.hi.z;
  if (f.count == 0) { // a bed height: the loose bed's part only
    shape.hi.z = shape.floor_z + loose_factor * f.bed_height;
    if (shape.cylinder)
      shape.length = std::fmin(shape.length, loose_factor * f.bed_height);
  }
  return shape;
}

void require_clear_of_walls(const std::vector<SceneWall>& walls, SceneFillShape& shape,
                            double bed_top, const std::string& clear_above_names) {
  const auto names = scene_names(clear_above_names, "Scene/Fill/Clear above");
  const std::set<std::string> clear_above(names.begin(), names.end());
  for (const auto& w : walls) {
    const auto& m = w.surface.mesh;
    if (!m.vertices.empty() && shape.contains_all(m.vertices)) {
      const meshes::BoundingBox box = meshes::bounding_box(m);
      const bool closed = meshes::check_closed(m).closed();
      const double volume = closed ? meshes::enclosed_volume(m) : 0; // [m^3] signed
      shape.submerged.push_back(
          {box, volume > 0 ? std::make_shared<const meshes::SolidRegion>(
                                 m, "Scene/Wall " + w.parameters.name + " (submerged in the fill)")
                           : nullptr});
      if (clear_above.count(w.parameters.name))
        shape.cleared_above.push_back(box);
      if (closed && box.max.z > box.min.z)
        shape.submerged_volume +=
            std::fabs(volume) *
            std::clamp((bed_top - box.min.z) / (box.max.z - box.min.z), 0.0, 1.0);
      continue;
    }
    if (clear_above.count(w.parameters.name))
      throw std::invalid_argument("Scene/Fill/Clear above: wall '" + w.parameters.name +
                                  "' does not stand wholly inside " + shape.describe() +
                                  " (only a submerged wall can be kept clear above)");
    for (std::size_t f = 0; f < m.n_faces(); ++f) {
      const auto& t = m.triangles[f];
      const Vec3 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
      if (!shape.cuts(a, b, c))
        continue;
      const Vec3 at = (a + b + c) / 3.0;
      std::ostringstream s;
      s << "Scene/Fill: " << shape.describe();
      if (wall_source_of(w.parameters).source == WallSource::file)
        s << " intersects wall '" << w.parameters.name << "' ('" << w.parameters.file << "', unit "
          << w.parameters.unit << ")";
      else
        s << " intersects wall '" << w.parameters.name << "' (" << w.parameters.source << ")";
      s << " near (" << at.x << ", " << at.y << ", " << at.z
        << ") m: particles would start inside it; move the region clear of the walls";
      throw std::invalid_argument(s.str());
    }
  }
}

} // namespace wear::dem
