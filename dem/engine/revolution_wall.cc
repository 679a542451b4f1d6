// Walls that are bounded surfaces of revolution: exact closest points, no triangles.
//
// Coordinates about the axis (unit a through P): for a point c, d = c - P, s = d . a, the
// in-plane part q = d - s a, rho = |q|. Distances are unsigned (two-sided, as for triangles);
// the contact normal points from the closest point p to c.
//
// Cylinder of radius R, a0 <= s <= a1: the distance^2 to the surface point (R, phi, s') is
// rho^2 + R^2 - 2 rho R cos(phi - theta) + (s - s')^2, least at phi = theta and
// s' = clamp(s, a0, a1):  p = P + clamp(s, a0, a1) a + R q / rho  (e1 for q = 0, where every
// point of the circle is equally close). Beyond an end the closest point is on the rim.
//
// Cone frustum, a0 <= s <= a1, radius R(s) going linearly from R0 at a0 to R1 at a1 (R0, R1 >=
// 0): as for the cylinder, the distance^2 to a surface point (R', phi, s') is least at
// phi = theta for every generator point (R' >= 0, rho >= 0), so p lies in c's meridional
// half-plane, at the closest point of the generator segment (R0, a0) .. (R1, a1) to
// (rho, s) in that plane:  t = clamp(((rho - R0) dR + (s - a0) ds) / (dR^2 + ds^2), 0, 1),
// p = P + (a0 + t ds) a + (R0 + t dR) q / rho  (e1 for q = 0).
//
// Annulus in the plane s = h, r0 <= rho <= r1, theta0 <= theta <= theta1: the height offset
// s - h is common to every point of the plane, so p is the closest point in the plane to q.
//  - theta within the range (or a full circle): the radial clamp
//      p = P + h a + clamp(rho, r0, r1) q / rho   (q = 0: along the theta0 edge, or e1).
//    Inside rho in [r0, r1] it is q itself; outside, the radial projection onto the circle
//    r1 (or r0) is the closest point of that whole circle region, and it lies in the range.
//  - theta outside the range: the closest point is on the boundary, and on an arc of radius r
//    the distance^2 rho^2 + r^2 - 2 rho r cos(phi - theta) is least at the arc's end nearer
//    in angle, which is also an end of a radial edge. So p is the nearer of the closest
//    points of the two radial edge segments {t u_k, r0 <= t <= r1}, u_k the unit edge
//    directions:  p_k = P + h a + clamp(q . u_k, r0, r1) u_k  (the projection onto the ray
//    clamped to the segment, not a clamp of the polar angle); on a tie the theta0 edge.
//  "Within the range" is decided by signs instead of atan2: with c0 = (u0 x q) . a and
//  c1 = (q x u1) . a, a range up to pi wide holds q when c0 >= 0 and c1 >= 0; a wider one
//  unless q lies strictly inside the complement (u1 x q) . a > 0 and (q x u0) . a > 0. Round-off
//  can only misplace a q within round-off of an edge, where both branches give the same p.
//
// Wear accounting: a contact's extensive integrals go to the face of the accounting
// triangulation whose closest point to the contact point is nearest (lowest index on ties);
// an accounting of one face (a wall whose loads are wanted as totals) takes every contact
// without a search.
// The accounting grid registers faces within the longest edge length; a point farther than
// that from every listed face (off the triangulated part) falls back to a scan of all faces.
#include "dem/engine/revolution_wall.h"

#include "meshes/constants.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace wear::dem {

using meshes::cross;
using meshes::dot;
using meshes::norm;
using meshes::normalized;

namespace {

bool finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
} // namespace

RevolutionSurface RevolutionSurface::cylinder(double radius, double axial_min, double axial_max) {
  RevolutionSurface s;
  s.kind = RevolutionKind::cylinder;
  s.radius = radius;
  s.axial_min = axial_min;
  s.axial_max = axial_max;
  return s;
}

RevolutionSurface RevolutionSurface::cone(double r_min, double r_max, double axial_min,
                                          double axial_max) {
  RevolutionSurface s;
  s.kind = RevolutionKind::cone;
  s.radius = r_min;
  s.radius_top = r_max;
  s.axial_min = axial_min;
  s.axial_max = axial_max;
  return s;
}

RevolutionSurface RevolutionSurface::annulus(double height, double r0, double r1, double th0,
                                             double th1) {
  RevolutionSurface s;
  s.kind = RevolutionKind::annulus;
  s.height = height;
  s.inner_radius = r0;
  s.outer_radius = r1;
  s.theta_min = th0;
  s.theta_max = th1;
  return s;
}

RevolutionWall::RevolutionWall(const RevolutionSurface& surface, int material_id,
                               const WallMotion& motion, bool wearing, std::string name,
                               const meshes::SurfaceMesh* accounting)
    : surface_(surface), material_(material_id), motion_(motion), wearing_(wearing),
      name_(std::move(name)) {
  check_surface();
  surface_.axis = normalized(surface_.axis);
  const Vec3& a = surface_.axis;
  const Vec3 ref = std::abs(a.x) > std::cos(25 * pi / 180) ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
  e1_ = normalized(ref - a * dot(ref, a));
  e2_ = cross(a, e1_);
  const double width = surface_.theta_max - surface_.theta_min;
  full_circle_ = surface_.kind != RevolutionKind::annulus || width >= 2 * pi * (1 - 1e-12);
  wide_ = width > pi;
  edge0_ = e1_ * std::cos(surface_.theta_min) + e2_ * std::sin(surface_.theta_min);
  edge1_ = e1_ * std::cos(surface_.theta_max) + e2_ * std::sin(surface_.theta_max);
  omega_ = normalized(motion_.axis) * motion_.angular_velocity;
  if (wearing_ && !accounting)
    throw std::invalid_argument("revolution wall '" + name_ +
                                "' is wearing but has no accounting mesh: per-face wear needs a "
                                "triangulation of the same surface");
  if (accounting)
    set_accounting(*accounting);
}

void RevolutionWall::check_surface() const {
  const auto require = [&](bool ok, const std::string& what) {
    if (!ok)
      throw std::invalid_argument("revolution wall '" + name_ + "': " + what);
  };
  const auto& s = surface_;
  require(finite(s.axis_point) && finite(s.axis) && norm(s.axis) > 0,
          "the axis needs a finite point and a nonzero direction");
  if (s.kind != RevolutionKind::annulus) {
    if (s.kind == RevolutionKind::cylinder)
      require(s.radius > 0 && std::isfinite(s.radius), "the radius must be positive [m]");
    else
      require(s.radius >= 0 && s.radius_top >= 0 && std::isfinite(s.radius) &&
                  std::isfinite(s.radius_top) && s.radius + s.radius_top > 0,
              "the radii must be finite, not negative and not both 0 [m]");
    require(std::isfinite(s.axial_min) && std::isfinite(s.axial_max) && s.axial_max > s.axial_min,
            "the axial extent must be finite and non-empty [m]");
    return;
  }
  require(std::isfinite(s.height), "the height must be finite [m]");
  require(s.inner_radius >= 0 && std::isfinite(s.outer_radius) && s.outer_radius > s.inner_radius,
          "the radii must satisfy 0 <= inner < outer [m]");
  require(std::isfinite(s.theta_min) && std::isfinite(s.theta_max) && s.theta_max > s.theta_min &&
              s.theta_max - s.theta_min <= 2 * pi * (1 + 1e-12),
          "the angular range must be non-empty and at most 2 pi [rad]");
}

RevolutionWall::Meridian RevolutionWall::meridian(const Vec3& c) const {
  const auto& s = surface_;
  const Vec3 d = c - s.axis_point;
  const double along = dot(d, s.axis);
  const Vec3 q = d - s.axis * along;
  const double rho = norm(q);
  return {along, rho, rho > 0 ? q / rho : e1_};
}

Vec3 RevolutionWall::closest_on_cylinder(const Vec3& c) const {
  const auto& s = surface_;
  const auto [along, rho, u] = meridian(c);
  return s.axis_point + s.axis * std::clamp(along, s.axial_min, s.axial_max) + u * s.radius;
}

Vec3 RevolutionWall::closest_on_cone(const Vec3& c) const {
  const auto& s = surface_;
  const auto [along, rho, u] = meridian(c);
  const double dr = s.radius_top - s.radius, ds = s.axial_max - s.axial_min;
  const double t = std::clamp(
      ((rho - s.radius) * dr + (along - s.axial_min) * ds) / (dr * dr + ds * ds), 0.0, 1.0);
  return s.axis_point + s.axis * (s.axial_min + t * ds) + u * (s.radius + t * dr);
}

bool RevolutionWall::within_angle(const Vec3& q) const {
  const Vec3& a = surface_.axis;
  if (!wide_)
    return dot(cross(edge0_, q), a) >= 0 && dot(cross(q, edge1_), a) >= 0;
  return !(dot(cross(edge1_, q), a) > 0 && dot(cross(q, edge0_), a) > 0);
}

Vec3 RevolutionWall::closest_on_annulus(const Vec3& c) const {
  const auto& s = surface_;
  const Vec3 d = c - s.axis_point;
  const Vec3 q = d - s.axis * dot(d, s.axis);
  const Vec3 base = s.axis_point + s.axis * s.height;
  if (full_circle_ || within_angle(q)) {
    const double rho = norm(q);
    const Vec3 u = rho > 0 ? q / rho : (full_circle_ ? e1_ : edge0_);
    return base + u * std::clamp(rho, s.inner_radius, s.outer_radius);
  }
  const Vec3 p0 = edge0_ * std::clamp(dot(q, edge0_), s.inner_radius, s.outer_radius);
  const Vec3 p1 = edge1_ * std::clamp(dot(q, edge1_), s.inner_radius, s.outer_radius);
  return base + (meshes::norm2(q - p1) < meshes::norm2(q - p0) ? p1 : p0);
}

void RevolutionWall::set_accounting(const meshes::SurfaceMesh& mesh) {
  auto wall = std::make_shared<MeshWall>(mesh, material_, motion_, false, name_ + " (accounting)");
  const auto& s = surface_;
  const double scale = s.kind == RevolutionKind::annulus
                           ? s.outer_radius
                           : std::max({s.radius, s.radius_top, s.axial_max - s.axial_min});
  for (std::size_t v = 0; v < mesh.n_vertices(); ++v) {
    const double off = distance(mesh.vertices[v]);
    if (!(off <= 1e-6 * scale))
      throw std::invalid_argument("revolution wall '" + name_ + "': vertex " + std::to_string(v) +
                                  " of the accounting mesh lies " + std::to_string(off) +
                                  " m off the surface; it must triangulate the same surface");
  }
  double longest = 0;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, norm(mesh.vertices[t[k]] - mesh.vertices[t[(k + 1) % 3]]));
  search_ = longest;
  wall->build_grid(search_);
  accounting_ = std::move(wall);
}

std::uint32_t RevolutionWall::accounting_face(const Vec3& p) const {
  const MeshWall& m = *accounting_;
  if (m.n_faces() == 1) // the wall's loads as one face: nothing to search
    return 0;
  std::uint32_t best = ~0u;
  double best_d2 = std::numeric_limits<double>::infinity();
  const auto consider = [&](std::uint32_t f) {
    const double d2 = meshes::norm2(m.closest(f, p).point - p);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = f;
    }
  };
  const auto listed = m.candidates(p);
  for (const std::uint32_t* f = listed.first; f != listed.second; ++f)
    consider(*f);
  if (best == ~0u || best_d2 > search_ * search_) {
    // Off the grid's reach: every face, from the first, so the lowest index wins ties.
    best = ~0u;
    best_d2 = std::numeric_limits<double>::infinity();
    for (std::uint32_t f = 0; f < m.n_faces(); ++f)
      consider(f);
  }
  return best;
}

} // namespace wear::dem
